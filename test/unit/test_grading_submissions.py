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
    from exp_assignment2.grading.paths import SIMULATOR
    from exp_assignment2.grading.peer import runs_our_simulator
    assert os.path.exists(SIMULATOR)
    link = tmp_path / 'scripts'
    os.symlink(os.path.dirname(SIMULATOR), str(link))     # the overlay's link farm
    assert runs_our_simulator(['/usr/bin/python3', str(link / 'simulator.py'), '__name:=x'])
    fake = tmp_path / 'simulator.py'
    fake.write_text('print("I am the simulator")')
    assert not runs_our_simulator(['/usr/bin/python3', str(fake)])
    assert not runs_our_simulator(['/usr/bin/python3', '-c', 'x', SIMULATOR + 'x'])
    # the script is what python runs, not any word of the command line
    assert not runs_our_simulator(['/usr/bin/python3', str(fake), SIMULATOR])
    assert not runs_our_simulator(['/usr/bin/python3', '-c', 'import os', SIMULATOR])
    assert not runs_our_simulator(['/usr/bin/python3', '-m', 'http.server', SIMULATOR])
    assert runs_our_simulator(['/usr/bin/python3', '-u', '-X', 'dev', SIMULATOR])
    # a program that only names itself python does not pass for it
    assert not runs_our_simulator([SIMULATOR], executable='/usr/bin/python3.11')
    assert not runs_our_simulator(['/usr/bin/python3', SIMULATOR], executable='/tmp/evil')
    assert runs_our_simulator(['/usr/bin/python3', SIMULATOR], executable='/usr/bin/python3.11')


CATKIN_RELAY = '/usr/share/catkin/cmake/templates/script.py.in'


def _relay(path, script):
    with open(CATKIN_RELAY) as f:
        text = f.read()
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text.replace('@PYTHON_EXECUTABLE@', '/usr/bin/python3')
                    .replace('@PYTHON_SCRIPT@', script))
    return str(path)


@pytest.mark.skipif(not os.path.exists(CATKIN_RELAY), reason='catkin is not installed')
def test_the_simulator_through_catkins_devel_and_install_spaces(tmp_path):
    """roslaunch of this package in a workspace starts devel/lib/.../simulator.py,
    catkin's relay to the source; an install space holds a copy with its own
    first line. Both are the simulator; a relay to another script, an edited
    copy, or any of them in a place the run can write, are not."""
    from exp_assignment2.grading.paths import SIMULATOR
    from exp_assignment2.grading.peer import runs_our_simulator, runs_simulator_file
    relay = _relay(tmp_path / 'ws' / 'devel' / 'lib' / 'exp_assignment2' / 'simulator.py',
                   SIMULATOR)
    assert runs_simulator_file(relay) == 'relay'
    assert runs_our_simulator(['/usr/bin/python3', relay, '__name:=gazebo'])
    # the workspace's src links to the repository, as tools/run makes it
    os.symlink(os.path.dirname(os.path.dirname(SIMULATOR)), str(tmp_path / 'src_link'))
    linked = _relay(tmp_path / 'ws2' / 'simulator.py',
                    str(tmp_path / 'src_link' / 'scripts' / 'simulator.py'))
    assert runs_our_simulator(['/usr/bin/python3', linked])
    fake = tmp_path / 'fake.py'
    fake.write_text('print("I am the simulator")')
    other = _relay(tmp_path / 'ws3' / 'simulator.py', str(fake))
    assert not runs_our_simulator(['/usr/bin/python3', other])
    with open(relay) as f:
        tampered = f.read() + 'import os\n'
    (tmp_path / 'tampered.py').write_text(tampered)
    assert not runs_our_simulator(['/usr/bin/python3', str(tmp_path / 'tampered.py')])
    with open(SIMULATOR) as f:
        source = f.read()
    installed = tmp_path / 'install' / 'lib' / 'exp_assignment2' / 'simulator.py'
    installed.parent.mkdir(parents=True)
    installed.write_text('#!/usr/bin/python3.11\n' + source.split('\n', 1)[1])
    assert runs_simulator_file(str(installed)) == 'copy'
    assert runs_our_simulator(['/usr/bin/python3', str(installed)])
    installed.write_text('#!/usr/bin/python3\n' + source.split('\n', 1)[1] + 'x = 1\n')
    assert not runs_our_simulator(['/usr/bin/python3', str(installed)])
    # the same relay in the run's writable directory: it could be changed after the start
    from exp_assignment2.grading.sandbox import mount_table, writable_at
    mounts = mount_table(str(tmp_path / 'ws'), hidden=[str(tmp_path)],
                         readonly=[str(tmp_path / 'ws2')])

    def may_write(path):
        return writable_at(path, mounts)
    assert not runs_our_simulator(['/usr/bin/python3', relay], may_write=may_write)
    assert runs_our_simulator(['/usr/bin/python3', linked], may_write=may_write)
    assert runs_our_simulator(['/usr/bin/python3', SIMULATOR], may_write=may_write)
    assert may_write('/tmp/x') and not may_write('/usr/lib/x')
    assert may_write(str(tmp_path / 'hidden_here')) and not may_write(linked)
