"""What the simulator tells a grader about each model, so that it can find
the robot, its head and the ball by their roles (sim.model_facts,
sim.ground_truth): offline, on the engine, no master."""
import os

from exp_assignment2.sim.engine import Engine
from exp_assignment2.sim.ground_truth import GroundTruth
from exp_assignment2.sim.model_facts import describe
from exp_assignment2.sim.offline import URDF_DIR
from exp_assignment2.sim.plugins.cores import CORES

HERE = os.path.dirname(os.path.abspath(__file__))
ROBOT = os.path.join(os.path.dirname(HERE), 'fixtures', 'spawned_robot.urdf')


class Link(object):
    """A ground-truth link that keeps what it is sent."""

    def __init__(self):
        self.records = []

    def send(self, record, droppable=False):
        self.records.append(record)

    def kinds(self, kind):
        return [r for r in self.records if r['kind'] == kind]


def world():
    engine = Engine(registry=CORES)
    with open(ROBOT) as f:
        engine.spawn('robot2', f.read(), (0, 0, 0.1, 0), namespace='robot2')
    with open(os.path.join(URDF_DIR, 'ball.urdf')) as f:
        engine.spawn('toy', f.read(), (3, 0, 0.5, 0), namespace='toy')
    return engine


def test_a_robot_is_described_by_what_drives_it_and_where_its_camera_is():
    engine = world()
    facts = describe(engine.models['robot2'], engine.plugins['robot2'])
    assert facts['namespace'] == 'robot2' and facts['root'] == 'base_link'
    drive = next(p for p in facts['plugins'] if p.get('drive'))
    assert drive['command'] == '/robot2/cmd_vel'
    assert drive['file'] == 'libgazebo_ros_diff_drive.so'
    # the camera's plugin is not served offline: its sensor is still known
    assert facts['sensors'] == [{'type': 'camera', 'name': 'cam', 'link': 'cam_link'}]
    assert facts['joints']['neck'] == {'type': 'revolute', 'parent': 'base_link',
                                       'child': 'head', 'axis': [0.0, 0.0, 1.0]}
    assert facts['joints']['cam_joint']['type'] == 'fixed'
    assert facts['sphere'] is None and not facts['static'] and not facts['kinematic']
    ball = describe(engine.models['toy'], engine.plugins['toy'])
    assert ball['sphere'] == 0.5 and ball['colour'] == [0.0, 0.8, 0.0, 1.0]
    assert ball['kinematic'] and [p['command'] for p in ball['plugins']] == ['/toy/cmd_vel']
    engine.close()


def test_the_ground_truth_says_each_model_once_and_who_commanded_what():
    engine = world()
    link = Link()
    truth = GroundTruth(engine, link)
    engine.step_listeners.append(truth)
    assert [r['facts']['name'] for r in link.kinds('model')] == ['robot2', 'toy']
    drive = engine.plugins['robot2'][0]
    for _ in range(3):
        drive.command.command(0.3, 0.0, 0.0)
    engine.models['toy'].set_pose((2.0, 1.0, 20.0))      # the template's 'disappear'
    engine.run_for(0.3)
    last = link.kinds('state')[-1]
    assert last['fed'] == {'robot2': 3} and last['placed'] == {'toy': 1}
    # a model spawned later is described when it comes, one deleted is said gone
    with open(os.path.join(URDF_DIR, 'ball.urdf')) as f:
        engine.spawn('ball2', f.read(), (5, 5, 0.5, 0))
    engine.delete('toy')
    engine.run_for(0.1)
    assert [r['facts']['name'] for r in link.kinds('model')] == ['robot2', 'toy', 'ball2']
    assert [r['name'] for r in link.kinds('deleted')] == ['toy']
    # nothing commanded, nothing counted
    assert 'ball2' not in link.kinds('state')[-1].get('fed', {})
    engine.close()
