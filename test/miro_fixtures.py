"""MiRo submissions in the original's shape, for the grader's miro profile
(test/test_grader.py)."""
import os
import shutil

from grading_fixtures import BASE, HERE

MIRO_ORIGINAL = os.path.join(HERE, 'fixtures', 'miro_original')
MIRO_README = """# MiRo

Start the state manager first, then the rest:

    rosrun {package} miro_state_manager.py
    roslaunch {package} miro_user.launch
"""


def make_miro(dest, package='exp_assignment2'):
    """A MiRo submission in the original's shape (test/fixtures/miro_original's
    four nodes and the user's launch file), for the miro profile; its package
    named ``package`` (a student's own name: the world is then this package's
    ``exp_assignment2``, as a teacher's workspace has it)."""
    os.makedirs(os.path.join(dest, 'scripts'))
    os.makedirs(os.path.join(dest, 'launch'))
    for name in os.listdir(MIRO_ORIGINAL):
        target = os.path.join(dest, 'launch' if name.endswith('.launch') else 'scripts', name)
        shutil.copy(os.path.join(MIRO_ORIGINAL, name), target)
        if name.endswith('.py'):
            os.chmod(target, 0o755)
    for name in ('package.xml', 'CMakeLists.txt'):
        with open(os.path.join(BASE, name)) as f:
            text = f.read()
        with open(os.path.join(dest, name), 'w') as f:
            f.write(text.replace('exp_assignment2', package))
    for name in os.listdir(os.path.join(dest, 'launch')):
        path = os.path.join(dest, 'launch', name)
        with open(path) as f:
            text = f.read()
        with open(path, 'w') as f:
            f.write(text.replace('exp_assignment2', package))
    with open(os.path.join(dest, 'README.md'), 'w') as f:
        f.write(MIRO_README.format(package=package))
    return dest
