"""A git repository of the submissions folder is read in plain Python
with dulwich under the grader's rules (grading/entry/git_objects.py,
git_packs.py, git_entries.py): its commit's tree as ``git archive`` gives it,
loose or packed (deltas, index versions 1 and 2), and nothing of its
configuration or hooks ever run (the bounds: test_grading_git_reading.py)."""
import io
import os
import subprocess
import tarfile

import pytest

from git_helpers import commit, git, make_hostile, make_repository, write
from exp_assignment2.grading.entry import git_entries
from exp_assignment2.grading.entry.copies import Copies
from exp_assignment2.grading.entry.git_objects import GitError, Repository
from exp_assignment2.grading.entry.submissions import Submission, discover, unpack
from exp_assignment2.grading.entry.unpacking import SubmissionError
from exp_assignment2.grading.run import tasks

DATES = ['2025-03-01T10:00:00+01:00', '2025-03-02T10:00:00+01:00',
         '2025-03-03T10:00:00+01:00']


def files_of(root):
    """{rel: (bytes or link text, executable)} of a folder."""
    out = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for name in filenames + [d for d in dirnames if os.path.islink(os.path.join(dirpath, d))]:
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, root)
            if os.path.islink(path):
                out[rel] = ('link', os.readlink(path))
            else:
                with open(path, 'rb') as f:
                    out[rel] = (f.read(), bool(os.stat(path).st_mode & 0o111))
    return out


def archived(repo, sha, dest):
    """The commit's tree as ``git archive`` writes it (the test's reference)."""
    data = subprocess.run(['git', '-C', repo, 'archive', '--format=tar', sha],
                          stdout=subprocess.PIPE, check=True,
                          env={'PATH': '/usr/bin:/bin', 'GIT_CONFIG_NOSYSTEM': '1',
                               'GIT_CONFIG_GLOBAL': '/dev/null', 'HOME': dest}).stdout
    with tarfile.open(fileobj=io.BytesIO(data)) as archive:
        archive.extractall(dest)
    return files_of(dest)


@pytest.fixture
def repo(tmp_path):
    path = str(tmp_path / 'class' / 'rossi')
    hashes = make_repository(path, DATES)
    write(path, 'scripts/helper', '#!/bin/sh\necho hi\n', 0o755)
    os.symlink('node.py', os.path.join(path, 'scripts', 'node_link.py'))
    os.symlink('/etc/passwd', os.path.join(path, 'scripts', 'out_link'))
    write(path, 'build/CMakeCache.txt', 'built\n')          # what catkin builds: never taken
    hashes.append(commit(path, 'the helper', '2025-03-04T10:00:00+01:00'))
    return path, hashes


def exported(path, sha, dest):
    submission = Submission('rossi', path, 'git', commit=sha)
    return unpack(submission, dest)


def test_discover_says_git_for_a_repository_and_dir_for_a_worktree_file(repo, tmp_path):
    path, _ = repo
    os.makedirs(str(tmp_path / 'class' / 'bianchi'))
    write(str(tmp_path / 'class' / 'bianchi'), '.git', 'gitdir: /elsewhere/.git\n')
    kinds = {s.name: s.kind for s in discover(str(tmp_path / 'class'))[0]}
    assert kinds == {'rossi': 'git', 'bianchi': 'dir'}


def test_the_tree_is_what_git_archive_gives_loose_and_packed(repo, tmp_path):
    path, hashes = repo
    reference = archived(path, hashes[-1], str(tmp_path / 'reference'))
    del reference['scripts/out_link']           # a link out: left out, with a note
    reference = {k: v for k, v in reference.items() if not k.startswith('build/')}
    loose = exported(path, hashes[-1], str(tmp_path / 'loose'))
    assert files_of(loose.dest) == reference
    assert reference['scripts/helper'][1] and not reference['package.xml'][1]
    assert any('out_link: left out: a link out' in n for n in loose.notes)
    git(path, 'repack', '-adf', '--depth=50', '--window=50')
    git(path, 'prune-packed')
    assert not [d for d in os.listdir(os.path.join(path, '.git', 'objects'))
                if len(d) == 2], 'every object packed'
    verify = git(path, 'verify-pack', '-v', *[
        os.path.join(path, '.git', 'objects', 'pack', n)
        for n in os.listdir(os.path.join(path, '.git', 'objects', 'pack')) if n.endswith('.idx')])
    assert 'chain length = 1' in verify, 'the pack holds deltas'
    for number, sha in enumerate(hashes):       # every commit, through the deltas
        want = archived(path, sha, str(tmp_path / ('ref%d' % number)))
        got = files_of(exported(path, sha, str(tmp_path / ('packed%d' % number))).dest)
        assert got == {k: v for k, v in want.items()
                       if k != 'scripts/out_link' and not k.startswith('build/')}


def test_an_index_of_version_1(repo, tmp_path):
    path, hashes = repo
    git(path, '-c', 'pack.indexVersion=1', 'repack', '-adf')
    git(path, 'prune-packed')
    got = files_of(exported(path, hashes[0], str(tmp_path / 'v1')).dest)
    assert b'VERSION = 1\n' in got['scripts/node.py'][0]


def test_nothing_of_a_hostile_repository_runs(repo, tmp_path):
    path, hashes = repo
    mark = str(tmp_path / 'marks')
    os.makedirs(mark)
    make_hostile(path, mark)
    submission = discover(str(tmp_path / 'class'))[0][0]
    facts = git_entries.choose(submission, {'late': {'per_day': 10}}, None)
    assert facts['commit'] == hashes[-1] and facts['subject'] == 'the helper'
    unpack(submission, str(tmp_path / 'out'))
    with Copies() as copies:        # what travels to a worker: the teacher's side's one copy
        kind, data = tasks.pack_submission(submission, copies)
        assert 'scripts/node.py' in files_of(copies.of(submission).taken().root)
    assert kind == 'tar'
    with tarfile.open(fileobj=io.BytesIO(data)) as archive:
        names = archive.getnames()
    assert any(n.endswith('scripts/node.py') for n in names)
    assert not any('/.git' in n or n.endswith('.git') for n in names)
    assert os.listdir(mark) == [], 'something of the repository ran'


def test_a_link_out_of_dot_git_is_refused(repo, tmp_path):
    path, hashes = repo
    objects = os.path.join(path, '.git', 'objects')
    os.rename(objects, str(tmp_path / 'elsewhere'))
    os.symlink(str(tmp_path / 'elsewhere'), objects)
    with pytest.raises(GitError):
        Repository(path).commit(hashes[0])
    with pytest.raises(SubmissionError, match='not a file of the repository'):
        exported(path, hashes[0], str(tmp_path / 'out'))


def test_the_deadline_takes_the_last_commit_before_it(repo):
    path, hashes = repo
    submission = Submission('rossi', path, 'git')
    facts = git_entries.choose(submission, {}, '2025-03-02T12:00:00+01:00')
    assert submission.commit == hashes[1]
    assert facts['after'] == 2 and facts['how'] == 'the last before the deadline'
    assert facts['date'] == '2025-03-02 10:00 +0100' and facts['subject'] == 'commit 2'
    assert facts['late_days'] == 0
    text = git_entries.summary(facts)
    assert text.startswith('graded at %s (2025-03-02 10:00 +0100, "commit 2")' % hashes[1][:7])
    assert '2 commits after it not graded' in text


def test_an_extension_moves_the_deadline(repo):
    path, hashes = repo
    submission = Submission('rossi', path, 'git')
    teacher = {'deadline': '2025-03-02T12:00:00+01:00',
               'extensions': {'rossi': '2025-03-03T12:00:00+01:00'}}
    facts = git_entries.choose(submission, teacher, None)
    assert submission.commit == hashes[2] and facts['extension'] and facts['after'] == 1
    assert facts['late_days'] == 0      # an extension is no lateness


def test_no_commit_before_the_deadline_is_not_built_saying_the_first(repo, tmp_path):
    path, hashes = repo
    submission = Submission('rossi', path, 'git')
    facts = git_entries.choose(submission, {}, '2025-02-01T00:00:00+01:00')
    assert submission.commit is None and facts['commit'] is None
    assert 'no commit before the deadline 2025-02-01 00:00 +0100' in submission.why
    assert hashes[0][:7] in submission.why and 'commit: "%s"' % hashes[0][:7] in submission.why
    with pytest.raises(SubmissionError, match='no commit before the deadline'):
        unpack(submission, str(tmp_path / 'out'))


def test_a_late_commit_chosen_on_purpose_loses_points_per_day_capped(repo):
    path, hashes = repo
    teacher = {'deadline': '2025-03-01T12:00:00+01:00', 'late': {'per_day': 10, 'max': 25},
               'submissions': {'rossi': {'commit': hashes[1][:8]}}}
    submission = Submission('rossi', path, 'git')
    facts = git_entries.choose(submission, teacher, None)
    assert submission.commit == hashes[1]
    assert (facts['late_days'], facts['late_points']) == (1, 10.0)     # 22 h late: one day
    teacher['submissions']['rossi'] = {'at': '2025-03-05T00:00:00+01:00'}
    facts = git_entries.choose(submission, teacher, None)
    assert submission.commit == hashes[3]
    assert (facts['late_days'], facts['late_points']) == (3, 25.0)     # 30 capped at 25
    assert '3 days late: 25 points off' in git_entries.summary(facts)
    del teacher['late']
    facts = git_entries.choose(submission, teacher, None)
    assert 'no late policy in grading.yaml' in git_entries.summary(facts)


def test_the_deadline_alone_never_grades_a_late_commit(repo):
    path, hashes = repo
    teacher = {'late': {'per_day': 10}}
    submission = Submission('rossi', path, 'git')
    facts = git_entries.choose(submission, teacher, '2025-03-01T12:00:00+01:00')
    assert submission.commit == hashes[0] and facts['late_points'] == 0


def test_a_tag_or_a_branch_names_a_commit(repo):
    path, hashes = repo
    git(path, 'tag', '-a', 'v1', '-m', 'first', hashes[0])
    git(path, 'branch', 'old', hashes[1])
    assert Repository(path).resolve('v1') == hashes[0]
    assert Repository(path).resolve('old') == hashes[1]
    with pytest.raises(GitError, match='no commit, tag or branch'):
        Repository(path).resolve('nope')


def test_the_first_parent_line_is_the_branch_as_it_stood(tmp_path):
    """A feature branch merged after the deadline: its commits, though dated
    before, were not on the branch at the deadline."""
    path = str(tmp_path / 'repo')
    make_repository(path, DATES[:1])
    git(path, 'checkout', '-q', '-b', 'feature')
    commit(path, 'feature work', '2025-03-02T09:00:00+01:00', {'scripts/feature.py': 'x = 1\n'})
    git(path, 'checkout', '-q', 'main')
    main = commit(path, 'main work', '2025-03-02T10:00:00+01:00', {'scripts/main.py': 'y = 2\n'})
    git(path, 'merge', '-q', '--no-ff', '-m', 'merge', 'feature',
        when='2025-03-04T10:00:00+01:00')
    submission = Submission('x', path, 'git')
    facts = git_entries.choose(submission, {}, '2025-03-03T00:00:00+01:00')
    assert submission.commit == main and facts['after'] == 2     # the feature and the merge


def test_a_repository_without_commit_is_graded_as_its_folder(tmp_path):
    path = str(tmp_path / 'class' / 'new')
    os.makedirs(path)
    git(path, 'init', '-q')
    write(path, 'package.xml', '<package/>')
    submission = discover(str(tmp_path / 'class'))[0][0]
    facts = git_entries.choose(submission, {}, None)
    assert submission.kind == 'dir' and 'no commit yet' in git_entries.summary(facts)
    assert os.path.isfile(os.path.join(unpack(submission, str(tmp_path / 'o')).dest,
                                       'package.xml'))


def test_files_changed_since_the_commit_are_counted(repo):
    path, hashes = repo
    write(path, 'scripts/node.py', 'changed\n')
    os.remove(os.path.join(path, 'launch', 'world.launch'))
    facts = git_entries.choose(Submission('rossi', path, 'git'), {}, None)
    assert facts['uncommitted'] == 2
    assert '2 files of the folder differ' in git_entries.summary(facts)


def test_an_object_that_is_not_what_its_name_says_is_refused(repo, tmp_path):
    path, hashes = repo
    repository = Repository(path)
    tree = repository.commit(hashes[0]).tree
    blob = next(sha for mode, name, sha in repository.tree(tree) if name == 'package.xml')
    loose = os.path.join(path, '.git', 'objects', blob[:2], blob[2:])
    other = Repository(path).commit(hashes[1]).tree
    os.chmod(loose, 0o644)
    with open(os.path.join(path, '.git', 'objects', other[:2], other[2:]), 'rb') as f:
        forged = f.read()
    with open(loose, 'wb') as f:
        f.write(forged)
    with pytest.raises(GitError, match='does not hold what its name says'):
        Repository(path).read(blob)


def test_a_sha256_repository_is_one_line(tmp_path):
    path = str(tmp_path / 'repo')
    os.makedirs(path)
    git(path, 'init', '-q', '--object-format=sha256')
    commit(path, 'first', DATES[0], {'package.xml': '<package/>'})
    submission = Submission('x', path, 'git')
    facts = git_entries.choose(submission, {}, None)
    assert facts['commit'] is None and 'SHA-256' in submission.why


def test_a_damaged_pack_is_one_line_not_a_crash(repo, tmp_path):
    path, hashes = repo
    git(path, 'repack', '-adf')
    git(path, 'prune-packed')
    folder = os.path.join(path, '.git', 'objects', 'pack')
    pack = os.path.join(folder, next(n for n in os.listdir(folder) if n.endswith('.pack')))
    os.chmod(pack, 0o644)
    with open(pack, 'r+b') as f:
        f.truncate(os.path.getsize(pack) // 2)
    submission = Submission('rossi', path, 'git')
    git_entries.choose(submission, {}, None)     # the commits come first in a pack
    with pytest.raises(SubmissionError, match='^the git repository: '):
        unpack(submission, str(tmp_path / 'out'))
    with open(pack, 'wb') as f:         # an empty one
        pass
    facts = git_entries.choose(Submission('rossi', path, 'git'), {}, None)
    assert 'is not a packfile' in facts['why']
