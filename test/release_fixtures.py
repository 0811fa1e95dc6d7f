"""The grader's fixtures of the ROS release a submission was written for
(issue 48): the dog as a Kinetic student wrote it (test/fixtures/grading/
kinetic_dog: it steers for Kinetic's diff drive, which honoured the URDF's
``legacyMode``), once saying so in its README and once saying nothing. The
fixture folder's ``grading.yaml`` makes Noetic the course's first release
(``FOLDER_SETTINGS``): the silent one fails there and passes when run again
in Kinetic, the better run counting.
"""
import os
import shutil

HERE = os.path.dirname(os.path.abspath(__file__))
KINETIC_DOG = os.path.join(HERE, 'fixtures', 'grading', 'kinetic_dog')

# name -> expected verdict
EXPECTED = {'kinetic_dog': 'passed', 'kinetic_silent': 'passed'}
FOLDER_SETTINGS = 'release: noetic    # the course\'s first ROS release (the fixtures are Noetic\'s)\n'
SILENT_README = """# My dog

Start everything with:

```
roslaunch exp_assignment2 gazebo_world.launch
```
"""


def kinetic_package(dest):
    """The Kinetic student's dog at ``dest``."""
    shutil.copytree(KINETIC_DOG, dest)
    os.chmod(os.path.join(dest, 'scripts', 'dog.py'), 0o755)
    return dest


def make(name, dest):
    """Write the fixture ``name`` into the class folder ``dest``."""
    path = kinetic_package(os.path.join(dest, name))
    if name == 'kinetic_silent':
        with open(os.path.join(path, 'README.md'), 'w') as f:
            f.write(SILENT_README)
    elif name != 'kinetic_dog':
        raise KeyError(name)
