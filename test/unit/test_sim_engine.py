"""The ROS-free engine: spawning and deleting models at run time, stepping,
resets, and the plugin contract (no master)."""
import math

import pytest

from exp_assignment2.sim.engine import Engine, SpawnError
from exp_assignment2.sim.plugins.base import Plugin, PluginError
from fakes import RecordingLog

BOX = '''<robot name="box">%s
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/>
    </inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
    <visual><geometry><box size="0.2 0.2 0.2"/></geometry></visual>
  </link>
</robot>'''


def box(gazebo=''):
    return BOX % gazebo


def plugin_tag(filename, options=''):
    return '<gazebo><plugin name="p" filename="%s">%s</plugin></gazebo>' % (filename, options)


class Recorder(Plugin):
    """Records every hook the engine calls, and when."""

    FILENAMES = ('librecorder.so',)
    calls = []

    def load(self):
        self.calls.append(('load', self.model.name, self.options.number('gain', 1.0),
                           self.namespace))

    def before_step(self):
        self.calls.append(('before', self.engine.time))

    def after_step(self):
        self.calls.append(('after', self.engine.time))

    def reset(self):
        self.calls.append(('reset', self.engine.time))

    def close(self):
        self.calls.append(('close', self.model.name))


class Refuser(Plugin):
    FILENAMES = ('librefuse.so',)

    def load(self):
        raise PluginError('model %s: I refuse' % self.model.name)


@pytest.fixture
def engine():
    Recorder.calls = []
    eng = Engine(registry={'librecorder.so': Recorder, 'librefuse.so': Refuser},
                 log=RecordingLog(),
                 real_time_factor=0)
    yield eng
    eng.close()


def test_spawn_step_and_delete_at_run_time(engine):
    engine.spawn('a', box(), (0, 0, 1, 0))
    engine.run_for(0.5)
    z = engine.models['a'].pose()[0][2]
    assert z < 0.5                                      # a dynamic box falls
    generation = engine.generation
    engine.spawn('b', box('<gazebo><static>true</static></gazebo>'), (1, 0, 1, 0, 0, 0))
    engine.run_for(0.5)
    assert engine.models['b'].pose()[0] == pytest.approx((1, 0, 1))   # static stays
    assert engine.generation == generation + 1
    engine.delete('a')
    assert list(engine.models) == ['b'] and engine.generation == generation + 2
    with pytest.raises(SpawnError, match='no model named'):
        engine.delete('a')


@pytest.mark.parametrize('name,text,pose,why', [
    ('a', box(), (0, 0, float('nan'), 0), 'not 6 finite numbers'),
    ('a', box(), (0, 0), 'not 6 finite numbers'),
    ('a', '<robot', (0, 0, 0, 0), 'not a valid URDF'),
    ('a', '<sdf version="1.6"/>', (0, 0, 0, 0), 'root element is <sdf>'),
    ('a', '<robot name="x"/>', (0, 0, 0, 0), 'has no link'),
    ('', box(), (0, 0, 0, 0), 'needs a name'),
])
def test_a_bad_spawn_is_refused_with_the_reason_and_changes_nothing(engine, name, text, pose,
                                                                  why):
    engine.spawn('first', box(), (0, 0, 0.1, 0))
    with pytest.raises(SpawnError, match=why):
        engine.spawn(name, text, pose)
    assert list(engine.models) == ['first']


def test_a_taken_name_is_refused(engine):
    engine.spawn('a', box(), (0, 0, 0.1, 0))
    with pytest.raises(SpawnError, match='exists already'):
        engine.spawn('a', box(), (1, 0, 0.1, 0))


def test_a_plugin_that_cannot_load_is_left_out_with_gazebo_line_and_the_model_stays(engine):
    text = box(plugin_tag('librefuse.so') + plugin_tag('librecorder.so'))
    model = engine.spawn('a', text)
    assert engine.models['a'] is model
    assert [type(pl).__name__ for pl in engine.plugins['a']] == ['Recorder']
    assert [t for level, t in engine.log.lines if level == 'error'] == [
        'model a: I refuse; Exception occured in the Load function of plugin with '
        'name[p] and filename[librefuse.so]. This plugin will not run.']


def test_the_hooks_run_in_order_in_the_simulation_thread(engine):
    engine.spawn('a', box(plugin_tag('librecorder.so', '<gain>2.5</gain>')), namespace='/ns/')
    assert Recorder.calls == [('load', 'a', 2.5, 'ns')]
    engine.run_for(0.02)
    assert Recorder.calls[1:] == [('before', 0.0), ('after', 0.01), ('before', 0.01),
                                  ('after', 0.02)]
    engine.reset_simulation()
    assert Recorder.calls[-1] == ('reset', 0.0) and engine.time == 0.0
    engine.delete('a')
    assert Recorder.calls[-1] == ('close', 'a')


def test_the_plugin_s_robot_namespace_wins_over_the_spawn_s(engine):
    """gazebo_ros_api_plugin gives the spawn's namespace only to plugins without one."""
    engine.spawn('a', box(plugin_tag('librecorder.so', '<robotNamespace>/r1</robotNamespace>')),
                 namespace='r2')
    engine.spawn('b', box(plugin_tag('librecorder.so')), (1, 0, 0, 0), namespace='r2')
    engine.spawn('c', box(plugin_tag('librecorder.so')), (2, 0, 0, 0))
    assert [c[3] for c in Recorder.calls if c[0] == 'load'] == ['r1', 'r2', '']


def test_an_unknown_plugin_gets_one_warning_naming_it(engine):
    engine.spawn('a', box(plugin_tag('libgazebo_ros_bumper.so')))
    engine.spawn('b', box(plugin_tag('libgazebo_ros_bumper.so')), (1, 0, 0, 0))
    warnings = [t for level, t in engine.log.lines if 'libgazebo_ros_bumper.so' in t]
    assert len(warnings) == 1 and 'not simulated here' in warnings[0]


def test_an_option_that_is_not_a_number_is_read_as_gazebo_reads_it(engine):
    """sdformat hands gazebo_ros a stream's read: ``fast`` is 0, ``2.5x`` is 2.5."""
    engine.spawn('a', box(plugin_tag('librecorder.so', '<gain>fast</gain>')))
    engine.spawn('b', box(plugin_tag('librecorder.so', '<gain>2.5x</gain>')), (1, 0, 0, 0))
    assert [c[2] for c in Recorder.calls if c[0] == 'load'] == [0.0, 2.5]
    assert [t for level, t in engine.log.lines if level == 'warn'] == [
        "model a: plugin p (librecorder.so): <gain> 'fast' is not a number: Gazebo reads it "
        "as 0"]


def test_call_soon_runs_work_in_the_loop_before_the_next_step(engine):
    seen = []
    engine.call_soon(lambda: seen.append(engine.steps))
    engine.run_for(0.01)
    assert seen == [0]
    assert engine.call_and_wait.__doc__


def test_the_guard_and_the_time(engine):
    engine.spawn('a', box(), (0, 0, 0.1, 0))
    engine.run_for(1.0)
    assert engine.time == pytest.approx(1.0) and engine.time_ns == 1000000000
    assert math.isfinite(engine.models['a'].pose()[0][2])


def test_a_library_no_gazebo_had_gets_gazebo_error_every_time(engine):
    engine.spawn('a', box(plugin_tag('libgazebo_ros_diffdrive.so')))
    engine.spawn('b', box(plugin_tag('libgazebo_ros_diffdrive.so')), (1, 0, 0, 0))
    assert [t for level, t in engine.log.lines if level == 'error'] == [
        'model %s: Failed to load plugin libgazebo_ros_diffdrive.so: libgazebo_ros_diffdrive.so: '
        'cannot open shared object file: No such file or directory' % name for name in 'ab']
    assert sorted(engine.models) == ['a', 'b']


GROUND = '''<robot name="ground"><gazebo><static>true</static></gazebo>
  <link name="base"><collision><origin xyz="0 0 -0.05"/>
    <geometry><box size="20 20 0.1"/></geometry></collision></link></robot>'''
JOINTED = '''<robot name="jointed">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/>
    </inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <link name="lid">
    <inertial><mass value="0.1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link>
  <joint name="hinge" type="revolute"><parent link="base"/><child link="lid"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>'''
SENSOR = ('<gazebo reference="base"><sensor type="camera" name="c"><update_rate>5</update_rate>'
          '</sensor></gazebo>')


def settle(engine, seconds=4.0):
    for _ in range(int(seconds / engine.time_step)):
        engine.step()


def test_a_still_jointless_body_comes_to_rest_and_what_is_done_to_it_wakes_it(engine):
    """As Gazebo's ODE auto-disables a model with no joint and no sensor: at
    rest it is not stepped (a raw teleport leaves it hanging), and a pose, a
    velocity or a body that hits it moves it again."""
    from exp_assignment2.sim.bullet import p
    engine.spawn('ground', GROUND, (0, 0, 0, 0, 0, 0))
    engine.spawn('barrel', box(), (0, 0, 0.5, 0, 0, 0))
    barrel = engine.models['barrel']
    assert barrel.may_rest
    settle(engine)
    assert barrel.pose()[0][2] == pytest.approx(0.1, abs=0.01)
    p.resetBasePositionAndOrientation(barrel.id, [0, 0, 1.0], [0, 0, 0, 1],
                                      physicsClientId=barrel.client)
    settle(engine, 0.5)
    assert barrel.pose()[0][2] == pytest.approx(1.0, abs=1e-6)      # at rest: not stepped
    barrel.set_pose((0, 0, 1.0))
    settle(engine, 0.5)
    assert barrel.pose()[0][2] < 0.5                                # a pose wakes it: it falls
    settle(engine)
    barrel.set_world_velocity((1.0, 0, 0), (0, 0, 0))
    settle(engine, 0.5)
    assert barrel.pose()[0][0] > 0.05                               # so does a velocity
    settle(engine)
    (x, y, z), _ = barrel.pose()
    barrel.set_pose((x, y, z), twist=((0, 1.0, 0), (0, 0, 0)))    # set_model_state's twist
    settle(engine, 0.5)
    assert barrel.pose()[0][1] > y + 0.05
    settle(engine)
    (x, y, z), _ = barrel.pose()
    engine.spawn('ram', box(), (x - 0.6, y, z, 0, 0, 0))
    engine.models['ram'].set_world_velocity((4.0, 0, 0), (0, 0, 0))
    settle(engine, 1.0)
    assert barrel.pose()[0][0] > x + 0.1                            # and a body that hits it


def test_a_body_at_rest_moves_its_joints_when_told(engine):
    """A model with joints and no plugin rests too; a joint command wakes it."""
    engine.spawn('ground', GROUND, (0, 0, 0, 0, 0, 0))
    engine.spawn('chest', JOINTED, (0, 0, 0.5, 0, 0, 0))
    chest = engine.models['chest']
    assert chest.may_rest
    settle(engine)
    chest.set_joint_velocity('hinge', 1.0, 10.0)
    settle(engine, 0.5)
    assert chest.joint_states(['hinge'])[1][0] > 0.2


@pytest.mark.parametrize('name, text', [
    ('driven', box(plugin_tag('librecorder.so'))), ('sensor', box(SENSOR)),
    ('never', box('<gazebo><allow_auto_disable>false</allow_auto_disable></gazebo>')),
    ('static', box('<gazebo><static>true</static></gazebo>')),
    ('kinematic', box('<gazebo reference="base"><gravity>0</gravity></gazebo>'))])
def test_a_driven_body_one_with_a_sensor_or_auto_disable_off_is_never_put_to_rest(engine, name,
                                                                                  text):
    engine.spawn(name, text, (0, 0, 0.5, 0, 0, 0))
    assert not engine.models[name].may_rest
