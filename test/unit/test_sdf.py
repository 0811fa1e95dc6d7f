"""SDF worlds read into URDF models (exp_assignment2.sim.sdf), no ROS: the
course's kind of world, shapes, poses, colours, meshes, and what cannot be read.

test/data/worlds/arena_like.world has the shape of the course's
world_assignment.world as Gazebo saved it: a sun, an inline ground plane,
model:// jersey barriers and construction barrels, a saved <state>.
"""
import os
import xml.etree.ElementTree as ET

import pytest

from exp_assignment2.sim.sdf import SdfError, model_to_urdf, read_world
from sdf_helpers import ARM, box_model, only, origin, rgba, shape, world

HERE = os.path.dirname(os.path.abspath(__file__))
ARENA = os.path.join(os.path.dirname(HERE), 'data', 'worlds', 'arena_like.world')


# the course's world

def test_the_arena_world_reads_as_gazebo_loads_it():
    w = read_world(ARENA, model_path=[])
    assert w.name == 'default' and w.gravity == (0.0, 0.0, -9.8)
    assert w.physics == {'max_step_size': 0.001, 'real_time_factor': 1.0,
                         'real_time_update_rate': 1000.0}
    assert [m.name for m in w.models] == ['ground_plane', 'jersey_barrier', 'jersey_barrier_clone',
                                          'red_box', 'post', 'Construction Barrel']
    statics = {m.name: m.static for m in w.models}
    assert statics['jersey_barrier'] and statics['ground_plane'] and statics['post']
    assert not statics['Construction Barrel']
    poses = {m.name: m.pose for m in w.models}
    # the saved <state> moves a model, as Gazebo applies it on load ...
    assert poses['jersey_barrier'][:2] == pytest.approx((-5.65677, 9.4608))
    # ... and a model it does not name stays at its own pose
    assert poses['jersey_barrier_clone'] == pytest.approx((9.45, 5.3, 0, 0, 0, -1.56865))
    assert poses['red_box'] == pytest.approx((2, -3, 0.25, 0, 0, 0.5))


def test_the_arena_world_says_once_per_mesh_which_box_stands_in():
    notes = read_world(ARENA, model_path=[]).notes
    assert notes == [
        'model://jersey_barrier/meshes/jersey_barrier.dae is not installed: a 4.07 x 0.81 x '
        '1.14 m box stands in (config/gazebo_model_sizes.yaml), in 2 models: jersey_barrier, '
        'jersey_barrier_clone',
        'model://construction_barrel/meshes/construction_barrel.dae is not installed: a 1.02 x '
        '1.02 x 1.55 m box stands in (config/gazebo_model_sizes.yaml), in 1 model: '
        'Construction Barrel']


def test_a_mesh_stand_in_is_the_known_box_standing_where_the_mesh_stood():
    models = {m.name: ET.fromstring(m.urdf) for m in read_world(ARENA, model_path=[]).models}
    barrier = models['jersey_barrier']
    assert shape(barrier) == ('box', {'size': '4.0656 0.8128 1.143'})
    assert origin(barrier)[0] == pytest.approx([0, 0, 0.5715])
    assert rgba(barrier) == (0.78, 0.78, 0.74, 1.0)
    # the model's own collision boxes are kept as they are
    assert [c.get('name') for c in barrier.findall('link/collision')] == ['upright', 'base']
    barrel = models['Construction Barrel']
    assert shape(barrel, 'collision') == ('box', {'size': '1.0199 1.0199 1.55'})
    assert barrel.find('link/inertial/mass').get('value') == '500'
    assert barrel.find('gazebo/static') is None


def test_every_model_of_the_arena_loads_in_pybullet(tmp_path):
    import pybullet
    client = pybullet.connect(pybullet.DIRECT)
    try:
        for m in read_world(ARENA, model_path=[]).models:
            path = tmp_path / ('%s.urdf' % m.name.replace(' ', '_'))
            path.write_text(m.urdf)
            body = pybullet.loadURDF(str(path), physicsClientId=client)
            assert body >= 0
            assert pybullet.getCollisionShapeData(body, -1, physicsClientId=client)
    finally:
        pybullet.disconnect(client)


# shapes, poses, colours

def test_boxes_cylinders_and_spheres_keep_their_sizes():
    assert shape(only(box_model('b'))[1]) == ('box', {'size': '1 2 3'})
    cyl = '<cylinder><radius>0.25</radius><length>2</length></cylinder>'
    assert shape(only(box_model('c', cyl))[1]) == ('cylinder', {'radius': '0.25', 'length': '2'})
    sphere = '<sphere><radius>0.5</radius></sphere>'
    assert shape(only(box_model('s', sphere))[1], 'collision') == ('sphere', {'radius': '0.5'})


def test_a_plane_is_a_thin_box_whose_top_face_is_the_plane():
    plane = '<plane><normal>0 0 1</normal><size>40 30</size></plane>'
    _, urdf = only(box_model('ground', plane))
    assert shape(urdf) == ('box', {'size': '40 30 0.02'})
    assert origin(urdf)[0] == pytest.approx([0, 0, -0.01])


def test_poses_compose_model_link_and_visual():
    extra = "<pose>0 0 1 0 0 0</pose>"
    text = box_model('m', pose='1 2 3 0 0 1.5', extra=extra).replace(
        "<visual name='visual'>", "<visual name='visual'><pose>0.5 0 0 0 0 0.25</pose>")
    model, urdf = only(text)
    assert model.pose == pytest.approx((1, 2, 3, 0, 0, 1.5))   # the model's pose: the spawn pose
    xyz, rpy = origin(urdf)
    assert xyz == pytest.approx([0.5, 0, 1]) and rpy == pytest.approx([0, 0, 0.25])
    assert origin(urdf, 'collision')[0] == pytest.approx([0, 0, 1])


def test_colours_diffuse_then_ambient_then_gazebo_script_names():
    def coloured(material):
        text = box_model('m').replace("<geometry>", "<material>%s</material><geometry>"
                                      % material, 1)
        return rgba(only(text)[1])
    assert coloured('<ambient>1 0 0 1</ambient><diffuse>0 0.5 0 1</diffuse>') == (0, 0.5, 0, 1)
    assert coloured('<ambient>0.2 0.3 0.4</ambient>') == (0.2, 0.3, 0.4, 1)
    assert coloured('<script><name>Gazebo/Blue</name></script>') == (0, 0, 1, 1)
    assert coloured('<script><name>Gazebo/NoSuch</name></script>') == (0.7, 0.7, 0.7, 1)


def test_a_scaled_mesh_stand_in_is_scaled():
    mesh = ('<mesh><uri>model://jersey_barrier/meshes/jersey_barrier.dae</uri>'
            '<scale>2 1 0.5</scale></mesh>')
    _, urdf = only(box_model('m', mesh))
    assert shape(urdf) == ('box', {'size': '8.1312 0.8128 0.5715'})
    assert origin(urdf)[0] == pytest.approx([0, 0, 0.28575])


def test_an_installed_stl_mesh_is_used_as_it_is(tmp_path):
    meshes = tmp_path / 'crate' / 'meshes'
    meshes.mkdir(parents=True)
    (meshes / 'crate.stl').write_text('solid crate\nendsolid crate\n')
    mesh = '<mesh><uri>model://crate/meshes/crate.stl</uri><scale>2 2 2</scale></mesh>'
    w = read_world(world(box_model('m', mesh)), model_path=[str(tmp_path)])
    assert shape(ET.fromstring(w.models[0].urdf)) == (
        'mesh', {'filename': str(meshes / 'crate.stl'), 'scale': '2 2 2'})
    assert w.notes == []


def test_an_installed_collada_mesh_of_an_unknown_model_is_the_default_box(tmp_path):
    (tmp_path / 'crate' / 'meshes').mkdir(parents=True)
    (tmp_path / 'crate' / 'meshes' / 'crate.dae').write_text('<COLLADA/>')
    mesh = '<mesh><uri>model://crate/meshes/crate.dae</uri></mesh>'
    w = read_world(world(box_model('m', mesh)), model_path=[str(tmp_path)])
    assert w.notes == [
        'model://crate/meshes/crate.dae is COLLADA, which the simulator does not load: a 1.00 '
        'x 1.00 x 1.00 m box stands in (the default for a model not in '
        'config/gazebo_model_sizes.yaml; seen, not collided with), in 1 model: m']


# what cannot be read

@pytest.mark.parametrize('text,message', [
    (world(box_model('jersey_barrier_0', '<cone><radius>1</radius></cone>')),
     'world/model[jersey_barrier_0]/link[link]/visual[visual]/geometry: unknown shape '
     '<cone>; accepted: box, cylinder, sphere, plane, mesh'),
    (world(box_model('m', pose='1 2 three 0 0 0')),
     "world/model[m]/pose: a pose must be 6 finite numbers, not '1 2 three 0 0 0'"),
    (world(box_model('m', pose='1 2 nan 0 0 0')),
     "world/model[m]/pose: a pose must be 6 finite numbers, not '1 2 nan 0 0 0'"),
    (world(box_model('m', '<box><size>1 -2 3</size></box>')),
     'world/model[m]/link[link]/visual[visual]/geometry/box/size: sizes must be positive, '
     'not 1 -2 3'),
    (world(box_model('m') + box_model('m')), "world/model[m]: two models are called 'm'"),
    (world(box_model('m').replace("<pose>0 0 0 0 0 0</pose>",
                                  "<pose relative_to='other'>0 0 0 0 0 0</pose>")),
     "world/model[m]/pose: a pose relative to frame 'other' is not supported; give it in the "
     "parent element's frame"),
    ('<robot name="r"><link name="l"/></robot>',
     'world: the root element is <robot>, not <sdf>: this is a URDF'),
    ("<sdf version='1.6'><model name='m'/></sdf>", 'world: no <world> in <sdf>'),
    ("<sdf version='1.6'><world>", 'world: not valid XML: no element found: line 1, column 26'),
])
def test_what_cannot_be_read_is_named(text, message):
    with pytest.raises(SdfError) as err:
        read_world(text, model_path=[])
    assert str(err.value) == message


@pytest.mark.parametrize('old,new,message', [
    ("type='revolute'", "type='hinge'",
     "model[arm]/joint[shoulder]: joint type 'hinge' is not an SDF joint type; accepted: "
     "revolute, continuous, prismatic, fixed, ball, universal, revolute2, screw, gearbox"),
    ('<child>upper</child>', '<child>forearm</child>',
     "model[arm]/joint[shoulder]: no link 'forearm' in model arm"),
])
def test_bad_joints_are_named(old, new, message):
    with pytest.raises(SdfError) as err:
        model_to_urdf(ARM.replace(old, new))
    assert str(err.value) == message


def test_a_missing_world_file_is_named(tmp_path):
    missing = str(tmp_path / 'nope.world')
    with pytest.raises(SdfError) as err:
        read_world(missing)
    assert str(err.value).startswith('%s: cannot read %s' % (missing, missing))


def test_sdf_error_is_a_value_error():
    assert issubclass(SdfError, ValueError)
