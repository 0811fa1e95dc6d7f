"""original-env --with DIR: more catkin packages built beside the user's, as a
class had them installed. The user's package (test/fixtures/notes_user)
imports the course's message package (test/fixtures/course_notes), which is
nowhere else: built with --with it is found by catkin, rospack and Python; the
build leaves both directories unchanged. A few minutes on two cores."""
import os
import shutil

import pytest

from test_overlay import WS, checksum, original_env

HERE = os.path.dirname(os.path.abspath(__file__))

pytestmark = [pytest.mark.skipif(not os.path.exists(os.path.join(WS, 'devel', 'setup.bash')),
                                 reason='no catkin workspace at %s: bash tools/run setup' % WS),
              pytest.mark.xdist_group('overlay')]


def test_a_course_package_given_with_is_built_beside_the_users(tmp_path):
    user, course = tmp_path / 'notes_user', tmp_path / 'course' / 'course_notes'
    shutil.copytree(os.path.join(HERE, 'fixtures', 'notes_user'), str(user))
    shutil.copytree(os.path.join(HERE, 'fixtures', 'course_notes'), str(course))
    before = checksum(user), checksum(course.parent)
    overlays = tmp_path / 'overlays'
    proc = original_env(user, '--with', str(course.parent), 'bash', '-ec',
                        'rospack find course_notes; rosrun notes_user print_note_type.py',
                        overlays=overlays)
    assert proc.returncode == 0, proc.stderr[-3000:]
    found, printed = proc.stdout.splitlines()[:2]
    assert os.path.realpath(os.path.join(found, 'package.xml')) == str(course / 'package.xml')
    kind, md5, module = printed.split()
    assert kind == 'course_notes/Note' and len(md5) == 32
    assert module.startswith(str(overlays)), module
    assert '; with course_notes from %s' % course.parent in proc.stderr
    assert (checksum(user), checksum(course.parent)) == before
    # without it the package builds (course_notes gets an empty CMake stand-in),
    # but its node cannot import the course's message: nothing else has it
    alone = original_env(user, 'rosrun', 'notes_user', 'print_note_type.py', overlays=overlays)
    assert alone.returncode == 1
    assert "No module named 'course_notes'" in alone.stderr, alone.stderr[-3000:]
