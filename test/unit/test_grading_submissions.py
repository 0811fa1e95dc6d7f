"""The grader reads a teacher's folder safely (exp_assignment2.grading.entry.submissions)."""
import io
import os
import tarfile
import zipfile

import pytest

from exp_assignment2.grading.entry import packages
from exp_assignment2.grading.entry.submissions import SubmissionError, discover, unpack

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


def unpack_root(submission, dest):
    return unpack(submission, dest).root


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
    (folder / 'grading.yaml').write_text('duration: 10\n')
    submissions, notes = discover(str(folder))
    assert [(s.name, s.kind) for s in submissions] == [
        ('alice', 'dir'), ('bob', 'dir'), ('carol', 'zip'), ('dave', 'tar')]
    assert notes == []
    before = snapshot(str(folder))
    names = []
    for s in submissions:
        root = unpack_root(s, str(tmp_path / 'runs' / s.name))
        names.append([p.name for p in packages.find(root)])
    assert names == [['exp_assignment2'], ['exp_assignment2'], ['carol_pkg'], ['dave_pkg']]
    assert snapshot(str(folder)) == before          # nothing in the folder was written


def test_every_entry_gets_a_row_whatever_it_is(tmp_path):
    """A loose file, a fifo, a link, a .rar: each a submission that cannot be
    taken, with why; the good one beside them is as it was."""
    folder = tmp_path / 'class'
    make_package(str(folder / 'good'))
    (folder / 'notes.txt').write_text('not a submission')
    os.mkfifo(str(folder / 'pipe'))
    os.symlink('/etc', str(folder / 'elsewhere'))
    (folder / 'old.rar').write_bytes(b'Rar!')
    submissions, notes = discover(str(folder))
    kinds = {s.name: (s.kind, s.why) for s in submissions}
    assert kinds['good'] == ('dir', None)
    assert kinds['notes.txt'][0] == 'other' and 'a single file' in kinds['notes.txt'][1]
    assert kinds['pipe'] == ('other', 'not a file nor a folder (a fifo, a socket or a device)')
    assert kinds['elsewhere'][0] == 'other' and 'a link (-> /etc), not followed' in \
        kinds['elsewhere'][1]
    assert kinds['old'][0] == 'other' and 'does not read' in kinds['old'][1]
    assert len(notes) == 4
    with pytest.raises(SubmissionError, match='a fifo'):
        unpack([s for s in submissions if s.name == 'pipe'][0], str(tmp_path / 'run'))


def test_one_package_is_one_submission(tmp_path):
    package = make_package(str(tmp_path / 'mine'))
    submissions, _ = discover(package)
    assert [(s.name, s.kind) for s in submissions] == [('mine', 'dir')]


def test_an_empty_folder_is_one_clear_line(tmp_path):
    (tmp_path / 'empty').mkdir()
    with pytest.raises(SubmissionError, match='no submissions in it'):
        discover(str(tmp_path / 'empty'))


@pytest.mark.parametrize('member', ['../escaped.txt', 'a/../../escaped.txt', '/tmp/escaped.txt'])
def test_a_member_out_of_the_archive_is_left_out(tmp_path, member):
    archive = tmp_path / 'bad.zip'
    with zipfile.ZipFile(str(archive), 'w') as z:
        z.writestr('pkg/package.xml', PACKAGE_XML % 'x')
        z.writestr(member, 'boo')
    submissions, _ = discover(str(archive))
    got = unpack(submissions[0], str(tmp_path / 'run'))
    assert got.notes == ['%s: left out: a path out of the archive' % member]
    assert [p.name for p in packages.find(got.root)] == ['x']
    assert not (tmp_path / 'escaped.txt').exists()
    assert not os.path.exists('/tmp/escaped.txt')


def _tar_link(t, name, target, kind=tarfile.SYMTYPE):
    info = tarfile.TarInfo(name)
    info.type, info.linkname = kind, target
    t.addfile(info)


def test_links_in_an_archive_kept_inside_left_out_when_they_point_out(tmp_path):
    archive = tmp_path / 'ws.tgz'
    with tarfile.open(str(archive), 'w:gz') as t:
        data = (PACKAGE_XML % 'dog').encode()
        info = tarfile.TarInfo('ws/src/dog/package.xml')
        info.size = len(data)
        t.addfile(info, io.BytesIO(data))
        _tar_link(t, 'ws/src/CMakeLists.txt', '/opt/ros/kinetic/share/catkin/cmake/toplevel.cmake')
        _tar_link(t, 'ws/src/dog/manifest.xml', 'package.xml')             # inside: kept
        _tar_link(t, 'ws/src/up', '.')
        _tar_link(t, 'ws/src/sneaky', 'up/../../../../etc')              # resolves out
        _tar_link(t, 'ws/src/dog/copy.xml', 'ws/src/dog/package.xml', tarfile.LNKTYPE)
    got = unpack(discover(str(archive))[0][0], str(tmp_path / 'run'))
    src = os.path.join(got.dest, 'ws', 'src')
    assert not os.path.lexists(os.path.join(src, 'CMakeLists.txt'))
    assert os.readlink(os.path.join(src, 'dog', 'manifest.xml')) == 'package.xml'
    assert open(os.path.join(src, 'dog', 'copy.xml')).read() == PACKAGE_XML % 'dog'
    assert not os.path.lexists(os.path.join(src, 'sneaky'))
    assert any('CMakeLists.txt: left out: a link out of the submission (-> /opt/ros/kinetic'
               in n for n in got.notes)
    assert any(n.startswith('ws/src/sneaky: left out: a link out') for n in got.notes)


def test_a_catkin_workspace_folder_copied_as_handed_in(tmp_path):
    """A workspace with catkin's toplevel link, committed build/ and devel/,
    a fifo and a link inside: the link out and the fifo left out, noted."""
    ws = tmp_path / 'class' / 'eve'
    package = make_package(str(ws / 'src' / 'exp_assignment2'))
    os.symlink('/opt/ros/kinetic/share/catkin/cmake/toplevel.cmake',
               str(ws / 'src' / 'CMakeLists.txt'))
    make_package(str(ws / 'devel' / 'share' / 'exp_assignment2'))
    (ws / 'build').mkdir()
    (ws / 'build' / 'Makefile').write_text('all:')
    os.mkfifo(os.path.join(package, 'fifo'))
    os.symlink('package.xml', os.path.join(package, 'alias.xml'))
    os.symlink('/etc', os.path.join(package, 'etc'))
    got = unpack(discover(str(tmp_path / 'class'))[0][0], str(tmp_path / 'run'))
    assert [p.rel for p in packages.find(got.dest)] == ['src/exp_assignment2']
    assert got.root == os.path.join(got.dest, 'src', 'exp_assignment2')   # what it wraps
    assert not os.path.exists(os.path.join(got.dest, 'build'))
    copy = got.root
    assert os.readlink(os.path.join(copy, 'alias.xml')) == 'package.xml'
    assert not os.path.lexists(os.path.join(copy, 'etc'))
    assert sorted(n.split(':')[0] for n in got.notes) == [
        'src/CMakeLists.txt', 'src/exp_assignment2/etc', 'src/exp_assignment2/fifo']


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


def test_packages_at_any_depth(tmp_path):
    (tmp_path / 'none').mkdir()
    (tmp_path / 'none' / 'README.md').write_text('hello')
    assert packages.find(str(tmp_path / 'none')) == []
    make_package(str(tmp_path / 'two' / 'a'), 'a')
    make_package(str(tmp_path / 'two' / 'b'), 'b')
    assert [p.name for p in packages.find(str(tmp_path / 'two'))] == ['a', 'b']
    make_package(str(tmp_path / 'deep' / 'x' / 'y' / 'z' / 'w'), 'w')
    make_package(str(tmp_path / 'deep' / 'x' / 'y' / 'z' / 'w' / 'inner'), 'inner')  # not seen
    make_package(str(tmp_path / 'deep' / 'ignored' / 'p'), 'p')
    (tmp_path / 'deep' / 'ignored' / 'CATKIN_IGNORE').write_text('')
    assert [(p.name, p.rel) for p in packages.find(str(tmp_path / 'deep'))] == [
        ('w', 'x/y/z/w')]


def test_only_the_repositorys_simulator_may_send_the_ground_truth(tmp_path):
    from exp_assignment2.grading.paths import SIMULATOR
    from exp_assignment2.grading.run.peer import runs_our_simulator
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
    from exp_assignment2.grading.run.peer import runs_our_simulator, runs_simulator_file
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
    from exp_assignment2.grading.run.sandbox import mount_table, writable_at
    mounts = mount_table(str(tmp_path / 'ws'), hidden=[str(tmp_path)],
                         readonly=[str(tmp_path / 'ws2')])

    def may_write(path):
        return writable_at(path, mounts)
    assert not runs_our_simulator(['/usr/bin/python3', relay], may_write=may_write)
    assert runs_our_simulator(['/usr/bin/python3', linked], may_write=may_write)
    assert runs_our_simulator(['/usr/bin/python3', SIMULATOR], may_write=may_write)
    assert may_write('/tmp/x') and not may_write('/usr/lib/x')
    assert may_write(str(tmp_path / 'hidden_here')) and not may_write(linked)
