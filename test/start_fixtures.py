"""Fixture submissions of how a student says to start the dog
(test/grading_fixtures.py writes them beside the others; test_grader.py
reads their grading): each is the dog that works, started another way.

* ``alternatives``: the README offers ``everything.launch``, or its world and the
  dog in two terminals, and a world with the ball elsewhere: one runs, the rest
  are noted; ``other_name``: a README written before package.xml was renamed;
* ``readme_cd_typo``: the world's launch file and the dog's apart; the
  README goes into ``launch/`` and runs the world's by its path, and names the
  dog's with a typo (``dog_beaviour.launch`` for ``dog_behavior.launch``);
* ``script_timing``: a start script opens a terminal for the dog, then runs
  the world's launch file itself; the dog waits at most 4 s for a latched
  topic a node of that launch file publishes, and raises without it. Typed
  in the script's text order, 5 s apart, the dog starts first and raises;
  started as the script's shell starts them, the launch file runs at once
  and the dog's terminal opens after it.
"""
import os
import re

EXPECTED = {'readme_cd_typo': 'passed', 'script_timing': 'passed'}
LAUNCH = os.path.join('launch', 'gazebo_world.launch')
DOG_NODE = '  <node name="dog" pkg="exp_assignment2" type="dog.py" output="screen"/>\n'

CD_TYPO_README = """# My dog

Go to the launch folder, `cd launch`, then start the world with
`roslaunch gazebo_world.launch`. In another terminal start the dog:
`roslaunch exp_assignment2 dog_beaviour.launch`.
"""
DOG_LAUNCH = '<launch>\n%s</launch>\n' % DOG_NODE

SCRIPT_README = """# My dog

Build it with `catkin_make`, then run `./start.sh`.
"""
START_SH = """#!/bin/bash
# the dog in a terminal of its own; the world in this one
gnome-terminal -x sh -c "rosrun exp_assignment2 dog.py; bash"
roslaunch --wait exp_assignment2 gazebo_world.launch
"""
READY_NODE = '''#!/usr/bin/env python3
"""Says, latched, that the world is up."""
import rospy
from std_msgs.msg import Bool

rospy.init_node('world_ready')
ready = rospy.Publisher('/world_ready', Bool, queue_size=1, latch=True)
ready.publish(Bool(True))
rospy.spin()
'''
READY_LAUNCH_NODE = '  <node name="world_ready" pkg="exp_assignment2" type="world_ready.py"/>\n'
# the dog's first act: the world must be up (rospy's wait: no wall clock in its code)
WAITS = """    rospy.init_node('dog')
    from std_msgs.msg import Bool
    rospy.wait_for_message('/world_ready', Bool, timeout=4.0)
"""


def _edit(dest, rel, change):
    path = os.path.join(dest, rel)
    with open(path) as f:
        text = f.read()
    changed = change(text)
    assert changed != text, rel
    with open(path, 'w') as f:
        f.write(changed)


def _write(dest, rel, text, mode=0o644):
    path = os.path.join(dest, rel)
    with open(path, 'w') as f:
        f.write(text)
    os.chmod(path, mode)


def readme_cd_typo(dest):
    _edit(dest, LAUNCH, lambda text: text.replace(DOG_NODE, ''))
    _write(dest, os.path.join('launch', 'dog_behavior.launch'), DOG_LAUNCH)
    _write(dest, 'README.md', CD_TYPO_README)


def script_timing(dest):
    _edit(dest, LAUNCH, lambda text: text.replace(DOG_NODE, READY_LAUNCH_NODE))
    _edit(dest, os.path.join('scripts', 'dog.py'),
          lambda text: text.replace("    rospy.init_node('dog')\n", WAITS))
    _write(dest, os.path.join('scripts', 'world_ready.py'), READY_NODE, 0o755)
    _write(dest, 'start.sh', START_SH, 0o755)
    _write(dest, 'README.md', SCRIPT_README)


# "everything.launch; alternatively these two in two terminals", and a world with
# the ball at random or at a fixed place: one world runs, the rest are noted
ALTERNATIVES = """# My dog

Start everything with:

    roslaunch exp_assignment2 everything.launch

Alternatively, in two terminals:

    roslaunch exp_assignment2 world_random.launch
    rosrun exp_assignment2 dog.py

For the ball at a fixed place: `roslaunch exp_assignment2 world_fixed.launch`
"""
# written before the package was renamed in package.xml (exp_assignment2)
OTHER_NAME = """# My dog

```
roslaunch assignment2 gazebo_world.launch
```
"""


def alternatives(dest):
    """everything.launch, and its world alone in two launch files the README offers."""
    launch = os.path.join(dest, 'launch')
    with open(os.path.join(launch, 'gazebo_world.launch')) as f:
        everything = f.read()
    world = re.sub(r'\n  <node name="dog".*?/>\n', '\n', everything)
    assert world != everything
    os.rename(os.path.join(launch, 'gazebo_world.launch'),
              os.path.join(launch, 'everything.launch'))
    for name, text in (('world_random.launch', world),
                       ('world_fixed.launch', world.replace('-x 4 -y 1.5', '-x 3 -y -2'))):
        with open(os.path.join(launch, name), 'w') as f:
            f.write(text)
    _write(dest, 'README.md', ALTERNATIVES)


MAKERS = {'readme_cd_typo': readme_cd_typo, 'script_timing': script_timing}
