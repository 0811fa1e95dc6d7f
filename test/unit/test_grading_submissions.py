"""The grader reads a teacher's folder safely (exp_assignment2.grading.submissions)."""
import io
import os
import tarfile
import zipfile

import pytest

from exp_assignment2.grading.submissions import SubmissionError, discover, find_package, \
    package_name, unpack

PACKAGE_XML = '<package format="2"><name>%s</name><version>0.0.1</version></package>'


def make_package(path, name='exp_assignment2'):
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, 'package.xml'), 'w') as f:
        f.write(PACKAGE_XML % name)
    return path


def snapshot(folder):
    """{path: (size, mtime)} of everything in a folder."""
    out = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            st = os.lstat(os.path.join(root, name))
            out[os.path.join(root, name)] = (st.st_size, st.st_mtime_ns)
    return out


def test_a_folder_of_directories_and_archives(tmp_path):
    folder = tmp_path / 'class'
    make_package(str(folder / 'alice'))
    make_package(str(folder / 'bob' / 'exp_assignment2'))          # one level down
    with zipfile.ZipFile(str(folder / 'carol.zip'), 'w') as z:
        z.writestr('carol/package.xml', PACKAGE_XML % 'carol_pkg')
    with tarfile.open(str(folder / 'dave.tar.gz'), 'w:gz') as t:
        data = (PACKAGE_XML % 'dave_pkg').encode()
        info = tarfile.TarInfo('package.xml')
        info.size = len(data)
        t.addfile(info, io.BytesIO(data))
    (folder / 'notes.txt').write_text('not a submission')
    (folder / 'grading.yaml').write_text('duration: 10\n')
    submissions, notes = discover(str(folder))
    assert [(s.name, s.kind) for s in submissions] == [
        ('alice', 'dir'), ('bob', 'dir'), ('carol', 'zip'), ('dave', 'tar')]
    assert notes == ['notes.txt: not a submission (a folder, .zip, .tar.gz or .tgz): skipped']
    before = snapshot(str(folder))
    names = []
    for s in submissions:
        names.append(package_name(unpack(s, str(tmp_path / 'runs' / s.name))))
    assert names == ['exp_assignment2', 'exp_assignment2', 'carol_pkg', 'dave_pkg']
    assert snapshot(str(folder)) == before          # nothing in the folder was written


def test_one_package_is_one_submission(tmp_path):
    package = make_package(str(tmp_path / 'mine'))
    submissions, _ = discover(package)
    assert [(s.name, s.kind) for s in submissions] == [('mine', 'dir')]


def test_an_empty_folder_is_one_clear_line(tmp_path):
    (tmp_path / 'empty').mkdir()
    with pytest.raises(SubmissionError, match='no submissions in it'):
        discover(str(tmp_path / 'empty'))


@pytest.mark.parametrize('member, message', [
    ('../escaped.txt', 'a path out of it'),
    ('a/../../escaped.txt', 'a path out of it'),
    ('/tmp/escaped.txt', 'an absolute path'),
])
def test_a_zip_that_escapes_is_refused(tmp_path, member, message):
    archive = tmp_path / 'bad.zip'
    with zipfile.ZipFile(str(archive), 'w') as z:
        z.writestr('pkg/package.xml', PACKAGE_XML % 'x')
        z.writestr(member, 'boo')
    submissions, _ = discover(str(archive))
    with pytest.raises(SubmissionError, match=message):
        unpack(submissions[0], str(tmp_path / 'run'))
    assert not (tmp_path / 'escaped.txt').exists()
    assert not os.path.exists('/tmp/escaped.txt')


def test_a_tar_link_out_of_it_is_refused(tmp_path):
    archive = tmp_path / 'bad.tgz'
    with tarfile.open(str(archive), 'w:gz') as t:
        info = tarfile.TarInfo('pkg/secret')
        info.type, info.linkname = tarfile.SYMTYPE, '/etc/shadow'
        t.addfile(info)
    submissions, _ = discover(str(archive))
    with pytest.raises(SubmissionError, match='a link out of it: pkg/secret -> /etc/shadow'):
        unpack(submissions[0], str(tmp_path / 'run'))


def test_a_directory_with_a_link_out_is_refused(tmp_path):
    package = make_package(str(tmp_path / 'class' / 'eve'))
    os.symlink('/etc', os.path.join(package, 'etc'))
    submissions, _ = discover(str(tmp_path / 'class'))
    with pytest.raises(SubmissionError, match='a link out of the submission'):
        unpack(submissions[0], str(tmp_path / 'run'))


def test_an_archive_too_large_is_refused(tmp_path):
    archive = tmp_path / 'big.zip'
    with zipfile.ZipFile(str(archive), 'w', zipfile.ZIP_DEFLATED) as z:
        z.writestr('pkg/package.xml', PACKAGE_XML % 'x')
        z.writestr('pkg/zeros', b'\0' * (3 * 1024 * 1024))
    submissions, _ = discover(str(archive))
    with pytest.raises(SubmissionError, match='more than 2 MB'):
        unpack(submissions[0], str(tmp_path / 'run'), limit=2 * 1024 * 1024)


def test_an_archive_that_does_not_unpack(tmp_path):
    (tmp_path / 'broken.zip').write_bytes(b'PK\x03\x04 not really')
    submissions, _ = discover(str(tmp_path / 'broken.zip'))
    with pytest.raises(SubmissionError, match='does not unpack'):
        unpack(submissions[0], str(tmp_path / 'run'))


def test_no_package_and_two_packages(tmp_path):
    (tmp_path / 'none').mkdir()
    (tmp_path / 'none' / 'README.md').write_text('hello')
    with pytest.raises(SubmissionError, match='no package.xml in it'):
        find_package(str(tmp_path / 'none'))
    make_package(str(tmp_path / 'two' / 'a'), 'a')
    make_package(str(tmp_path / 'two' / 'b'), 'b')
    with pytest.raises(SubmissionError, match='two packages in one submission: a, b'):
        find_package(str(tmp_path / 'two'))
    make_package(str(tmp_path / 'deep' / 'x' / 'y' / 'z' / 'w'))
    (tmp_path / 'deep' / 'x' / 'other').mkdir()
    with pytest.raises(SubmissionError, match='no package.xml at the top or one level down'):
        find_package(str(tmp_path / 'deep'))


def test_only_the_repositorys_simulator_may_send_the_ground_truth(tmp_path):
    from exp_assignment2.grading.truth import SIMULATOR, runs_our_simulator
    assert os.path.exists(SIMULATOR)
    link = tmp_path / 'scripts'
    os.symlink(os.path.dirname(SIMULATOR), str(link))     # the overlay's link farm
    assert runs_our_simulator(['/usr/bin/python3', str(link / 'simulator.py'), '__name:=x'])
    fake = tmp_path / 'simulator.py'
    fake.write_text('print("I am the simulator")')
    assert not runs_our_simulator(['/usr/bin/python3', str(fake)])
    assert not runs_our_simulator(['/usr/bin/python3', '-c', 'x', SIMULATOR + 'x'])
