"""The grader's fixtures for roslaunch's rules (test/grading_fixtures.py
writes them, each the working dog with one thing changed):

* ``helper_dies``: a ``robot_state_publisher`` that finds no
  ``robot_description`` (the dog's is in ``/robot``) and dies at start, as it
  did unnoticed on a student's desktop; ``respawn="true"``, so roslaunch
  restarts it again and again. roslaunch runs on, and so does the run:
  ``passed``, the death noted once;
* ``required_dies``: the dog is ``required="true"`` and raises after 3
  simulated s: roslaunch shuts its launch down, the run ends there
  (``required_node_died``) and is ``crashed``;
* ``xterm_dog``: the dog in a window of its own (``launch-prefix="xterm
  -e"``): ``passed``, its window captured, its output still in the log.
"""
import os

LAUNCH = os.path.join('launch', 'gazebo_world.launch')
DOG = os.path.join('scripts', 'dog.py')

HELPER_DIES = ('  <node name="robot_state_publisher" pkg="robot_state_publisher"\n'
               '        type="robot_state_publisher" respawn="true" respawn_delay="3"/>\n')
TIRED = 'RuntimeError: the dog is tired'
XTERM_SAYS = 'the dog plays in its own window'


def _edit(dest, rel, old, new):
    path = os.path.join(dest, rel)
    with open(path) as f:
        text = f.read()
    assert text.count(old) == 1, (rel, old)
    with open(path, 'w') as f:
        f.write(text.replace(old, new))


def helper_dies(dest):
    _edit(dest, LAUNCH, '</launch>', HELPER_DIES + '</launch>')


def required_dies(dest):
    _edit(dest, LAUNCH, 'type="dog.py" output="screen"/>',
          'type="dog.py" output="screen" required="true"/>')
    _edit(dest, DOG, """        dog.step()
        rate.sleep()""", """        dog.step()
        rate.sleep()
        if rospy.get_time() > 3.0:      # simulated s
            raise %s('%s')""" % tuple(TIRED.split(': ')))


def xterm_dog(dest):
    _edit(dest, LAUNCH, 'type="dog.py" output="screen"/>',
          'type="dog.py" output="screen" launch-prefix="xterm -e"/>')
    _edit(dest, DOG, "    dog = Dog()\n",
          "    dog = Dog()\n    rospy.loginfo('%s')\n" % XTERM_SAYS)


FIXTURES = {'helper_dies': helper_dies, 'required_dies': required_dies, 'xterm_dog': xterm_dog}
