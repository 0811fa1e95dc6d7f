"""A submission that is a git repository, graded at one commit (no ROS, no ``git``).

GitHub Classroom clones a folder of repositories; an entry of the folder with
a ``.git`` folder is graded at a commit, its tree taken as ``git archive``
would, without a checkout: no hook, no filter, nothing of its configuration
(:mod:`~exp_assignment2.grading.entry.git_objects` reads the objects with
dulwich). Which
commit (:func:`choose`), in this order:

1. grading.yaml's ``submissions: NAME: commit: HASH`` (a hash, tag or branch)
   or ``at: TIME`` (the last commit at or before TIME): chosen on purpose, so
   the late policy applies if it is past the student's deadline;
2. with a deadline (``--deadline``, grading.yaml's ``deadline:``, the
   student's ``extensions:``): the last commit at or before it, walking the
   checked-out branch back along its first parents (the branch as it stood
   then); none: the submission is ``not_built``, saying which was its first;
3. else the checked-out commit (``HEAD``).

A commit's time is its committer's, which the student's machine wrote: the
time of the push is GitHub's to tell. The facts chosen (:func:`choose`'s
dict: the commit, its date and subject, the commits after it not graded, the
deadline, late days and points) travel with every run and are on its pages.
"""
import os
import stat

from dulwich.objects import Blob

from exp_assignment2.grading.entry import deadlines
from exp_assignment2.grading.entry.git_objects import GitError, Repository
from exp_assignment2.grading.entry.unpacking import MAX_MEMBERS, MAX_UNPACKED, SKIPPED, \
    SubmissionError, _Budget, _make_links

MAX_HISTORY = 100000        # commits walked for the count of those not graded
MAX_DEPTH = 64              # folders in folders of a commit's tree (deeper: left out)
TREE, LINK, MODULE = 0o040000, 0o120000, 0o160000


def is_repository(path):
    """A folder with a ``.git`` folder of its own (not a link, not a worktree's file)."""
    git = os.path.join(path, '.git')
    return os.path.isdir(path) and not os.path.islink(git) and os.path.isdir(git)


def _dated(commit):
    import datetime
    zone = datetime.timezone(datetime.timedelta(minutes=commit.offset))
    return deadlines.shown(datetime.datetime.fromtimestamp(commit.time, zone))


def _ancestors(repo, sha, limit=MAX_HISTORY):
    """Every commit reachable from ``sha`` (parents not in the repository, as
    in a shallow clone, end the walk there)."""
    seen, queue = set(), [sha]
    while queue and len(seen) < limit:
        current = queue.pop()
        if current in seen:
            continue
        seen.add(current)
        try:
            queue.extend(repo.commit(current).parents)
        except GitError:
            pass
    return seen


def _before(repo, head, moment):
    """(the last commit at or before ``moment`` on the first-parent line from
    ``head``, or None; the oldest commit of that line)."""
    commit = repo.commit(head)
    for _ in range(MAX_HISTORY):
        if commit.time <= moment.timestamp():
            return commit, commit
        if not commit.parents:
            return None, commit
        try:
            commit = repo.commit(commit.parents[0])
        except GitError:        # a shallow clone's end
            return None, commit
    return None, commit


def choose(submission, teacher, cli_deadline=None):
    """The commit to grade ``submission`` (a Submission of kind ``git``) at:
    sets its ``commit``, or its ``why`` (it cannot be graded: no commit before
    the deadline, a repository that cannot be read), and returns the facts
    for its pages (JSON-safe). A repository with no commit yet is graded as
    the folder it is (kind ``dir``). TeacherFileError for a time that does not
    parse."""
    name = submission.name
    own = (teacher.get('submissions') or {}).get(name) or {}
    deadline, extended = deadlines.deadline_of(name, cli_deadline, teacher)
    facts = {'deadline': deadlines.shown(deadline) if deadline else None,
             'extension': extended, 'late_days': 0, 'late_points': 0.0, 'after': 0}
    try:
        repo = Repository(submission.path)
        head = repo.ref('HEAD')
        if head is None:
            submission.kind = 'dir'
            return dict(facts, commit=None, how='no commit', why='a git repository with no '
                        'commit yet: its files are graded as they are')
        if own.get('commit') is not None:
            chosen = repo.commit(repo.resolve(own['commit']))
            how = 'grading.yaml names it (commit: %s)' % own['commit']
        elif own.get('at') is not None:
            at = deadlines.parse_time(own['at'], 'grading.yaml: submissions: %s: at' % name)
            chosen, first = _before(repo, head, at)
            if chosen is None:
                raise GitError('no commit at or before %s (at: in grading.yaml); the first is '
                               '%s of %s' % (deadlines.shown(at), first.sha[:7], _dated(first)))
            how = 'the last at or before %s (grading.yaml: at:)' % deadlines.shown(at)
        elif deadline is not None:
            chosen, first = _before(repo, head, deadline)
            if chosen is None:
                raise GitError('no commit before the deadline %s%s: the first is %s of %s '
                               '(to grade it anyway, name it in grading.yaml: submissions: '
                               '%s: commit: "%s")' % (
                                   facts['deadline'], ' (an extension)' if extended else '',
                                   first.sha[:7], _dated(first), name, first.sha[:7]))
            how = 'the last before the deadline%s' % (' (an extension)' if extended else '')
        else:
            chosen, how = repo.commit(head), 'the checked-out commit'
        if own.get('commit') is not None or own.get('at') is not None:
            days, points = deadlines.late(chosen.time, deadline, teacher.get('late'))
            facts.update(late_days=days, late_points=points)
        later = _ancestors(repo, head) - _ancestors(repo, chosen.sha)
        facts.update(commit=chosen.sha, short=chosen.sha[:7], date=_dated(chosen),
                     subject=chosen.subject, how=how, after=len(later),
                     uncommitted=_changed(submission.path, repo, repo.commit(head).tree))
    except (GitError, OSError, ValueError) as exc:     # a damaged repository: the student's
        submission.why = 'the git repository: %s' % (getattr(exc, 'strerror', None) or exc)
        return dict(facts, commit=None, how='not read', why=submission.why)
    submission.commit = chosen.sha
    return facts


def summary(facts):
    """The facts in words: ``graded at abc1234 (2025-03-01 23:10 +0100, "Fix
    the head"), the last before the deadline 2025-03-02 00:00 +0100; 2
    commits after it not graded``."""
    if not facts.get('commit'):
        return facts.get('why') or ''
    parts = ['graded at %s (%s, "%s"), %s' % (facts['short'], facts['date'], facts['subject'],
                                              facts['how'])]
    if facts.get('deadline'):
        parts[0] += '; deadline %s%s' % (facts['deadline'], ' (an extension)'
                                         if facts.get('extension') else '')
    if facts.get('after'):
        parts.append('%d commit%s after it not graded' % (facts['after'],
                                                          's' if facts['after'] > 1 else ''))
    if facts.get('late_days'):
        parts.append('%d day%s late: %g points off%s' % (
            facts['late_days'], 's' if facts['late_days'] > 1 else '', facts['late_points'],
            '' if facts['late_points'] else ' (no late policy in grading.yaml)'))
    if facts.get('uncommitted'):
        parts.append('%d file%s of the folder differ from the checked-out commit (not '
                     'committed: not graded)' % (facts['uncommitted'],
                                                's' if facts['uncommitted'] > 1 else ''))
    return '; '.join(parts)


def export(submission, dest, out, limit):
    """The tree of ``submission.commit`` written into ``dest`` (an Unpacked
    ``out`` notes what is left out): files with their executable bit, links
    that stay inside, no submodule (another repository), nothing that catkin
    builds or version control keeps (as a folder's copy)."""
    if not submission.commit:
        raise SubmissionError(getattr(submission, 'why', None) or 'no commit chosen')
    try:
        repo = Repository(submission.path)
        budget, links, count = _Budget(limit, 'the commit holds'), [], [0]
        _write_tree(repo, repo.commit(submission.commit).tree, dest, '', budget, links, out,
                    count)
    except GitError as exc:
        raise SubmissionError('the git repository: %s' % exc)
    _make_links(dest, links, out)


def _write_tree(repo, tree, dest, rel, budget, links, out, count):
    for mode, name, sha in repo.tree(tree):
        path, here = os.path.join(dest, rel, name), os.path.join(rel, name)
        count[0] += 1
        if count[0] > MAX_MEMBERS:
            raise SubmissionError('the commit holds more than %d files' % MAX_MEMBERS)
        if name in ('', '.', '..') or '/' in name or '\0' in name or name.lower() == '.git':
            out.leave_out(here, 'a name git itself refuses to check out')
        elif name in SKIPPED:
            continue
        elif mode == TREE and here.count(os.sep) >= MAX_DEPTH:
            out.leave_out(here, 'more than %d folders deep' % MAX_DEPTH)
        elif mode == TREE:
            os.makedirs(path, exist_ok=True)
            _write_tree(repo, sha, dest, here, budget, links, out, count)
        elif mode == MODULE:
            out.leave_out(here, 'a submodule (another repository, not in this one)')
        elif mode == LINK:
            links.append((path, repo.blob(sha).decode('utf-8', 'replace'), here))
        elif stat.S_ISREG(mode):
            data = repo.blob(sha)
            budget.take(len(data))
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, 'wb') as f:
                f.write(data)
            os.chmod(path, 0o755 if mode & 0o111 else 0o644)
        else:
            out.leave_out(here, 'an entry of unknown kind (mode %o)' % mode)


def _changed(path, repo, tree, rel=''):
    """How many files of ``tree`` the folder holds otherwise (changed or
    removed since the checked-out commit: not graded). 0 when it cannot tell."""
    changed = 0
    try:
        entries = repo.tree(tree)
    except GitError:
        return 0
    for mode, name, sha in entries:
        full = os.path.join(path, rel, name)
        if mode == TREE and name not in SKIPPED and rel.count(os.sep) < MAX_DEPTH:
            changed += _changed(path, repo, sha, os.path.join(rel, name))
        elif stat.S_ISREG(mode):
            try:
                if os.path.islink(full) or os.path.getsize(full) > MAX_UNPACKED:
                    changed += 1
                    continue
                with open(full, 'rb') as f:
                    data = f.read()
            except OSError:
                changed += 1
                continue
            changed += Blob.from_string(data).id.decode('ascii') != sha
    return changed
