"""What Gazebo 11 loads, the SDF reader loads (exp_assignment2.sim.sdf), no ROS:
a static model's inertial is not checked, a massless link on a fixed joint is
kept with one warning, a mesh of an unknown model gets the default box with one
line; a heightmap, a model without a link and a ball joint load with a line
saying what is not simulated; what would break the world stays refused.

test/data/worlds/saved_shelter.world is a world as Gazebo saves one: a static,
visual-only model of mass 0 whose mesh belongs to a model this package does
not know, and a cart with a massless flag on a fixed joint.
"""
import os
import xml.etree.ElementTree as ET

import pytest

from exp_assignment2.sim.sdf import SdfError, model_to_urdf, read_world
from sdf_helpers import ARM, box_model, world

HERE = os.path.dirname(os.path.abspath(__file__))
SAVED = os.path.join(os.path.dirname(HERE), 'data', 'worlds', 'saved_shelter.world')


def _models(w):
    return {m.name: ET.fromstring(m.urdf) for m in w.models}


def test_a_world_gazebo_saved_loads_with_one_line_each_for_the_mesh_and_the_massless_link():
    w = read_world(SAVED, model_path=[])
    assert [m.name for m in w.models] == ['ground_plane', 'shelter', 'cart']
    assert w.notes == [
        'model://shelter_kit/meshes/shelter.dae is not installed: a 1.00 x 1.00 x 1.00 m box '
        'stands in (the default for a model not in config/gazebo_model_sizes.yaml; seen, not '
        'collided with), in 1 model: shelter']
    assert w.warnings == [
        'world/model[cart]/link[flag]: mass 0 on a dynamic link: it moves with link body as '
        "if lumped into it (Gazebo's fixed-joint reduction), adding no mass"]


def test_the_unknown_mesh_is_a_visual_box_of_the_default_size_scaled_and_no_collision():
    shelter = _models(read_world(SAVED, model_path=[]))['shelter']
    box = shelter.find('link/visual/geometry/box')
    assert box.get('size') == '2 2 2'
    assert shelter.find('link/visual/origin').get('xyz') == '0 0 1'
    assert shelter.find('link/collision') is None
    assert shelter.find('gazebo/static').text == 'true'


def test_the_massless_flag_adds_no_mass_and_rides_on_its_parent(tmp_path):
    import pybullet
    w = read_world(SAVED, model_path=[])
    cart = _models(w)['cart']
    assert [l.find('inertial/mass').get('value') for l in cart.findall('link')] == ['4', '0']
    client = pybullet.connect(pybullet.DIRECT)
    try:
        pybullet.setGravity(0, 0, -9.8, physicsClientId=client)
        ground = pybullet.createCollisionShape(pybullet.GEOM_PLANE, physicsClientId=client)
        pybullet.createMultiBody(0, ground, physicsClientId=client)
        path = tmp_path / 'cart.urdf'
        path.write_text([m for m in w.models if m.name == 'cart'][0].urdf)
        body = pybullet.loadURDF(str(path), [0, 0, 0.2], physicsClientId=client)
        for _ in range(500):
            pybullet.stepSimulation(physicsClientId=client)
        base = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0]
        flag = pybullet.getLinkState(body, 0, physicsClientId=client)[0]
        assert base[2] == pytest.approx(0.1, abs=0.01)          # it fell and rests: dynamic
        assert flag[2] - base[2] == pytest.approx(0.3, abs=0.01)
    finally:
        pybullet.disconnect(client)


def test_a_static_model_inertia_is_not_checked():
    text = world(box_model('m', extra='<inertial><mass>0</mass><inertia><ixx>0</ixx>'
                                      '<iyy>0</iyy><izz>0</izz></inertia></inertial>'))
    (model,) = read_world(text, model_path=[]).models
    assert ET.fromstring(model.urdf).find('link/inertial/mass').get('value') == '1'


@pytest.mark.parametrize('extra,message', [
    ('<inertial><mass>-2</mass></inertial>',
     'world/model[m]/link[link]/inertial/mass: must not be negative, not -2'),
    ('<inertial><mass>nan</mass></inertial>',
     "world/model[m]/link[link]/inertial/mass: the value must be 1 finite numbers, not 'nan'"),
    ('<inertial><mass>0</mass></inertial>',
     'world/model[m]/link[link]/inertial/mass: 0 on a dynamic link (the root link): Gazebo '
     "refuses it too (ODE: 'Setting custom link mass to zero!'); give it a mass, or make the "
     'model static'),
])
def test_what_would_break_the_world_is_still_refused(extra, message):
    text = world(box_model('m', extra=extra).replace('<static>1</static>', ''))
    with pytest.raises(SdfError) as err:
        read_world(text, model_path=[])
    assert str(err.value) == message


def test_a_massless_link_on_a_moving_joint_is_refused():
    upper = "<link name='upper'><pose>0 0 0.5 0 0 0</pose>"
    assert upper in ARM
    with pytest.raises(SdfError) as err:
        model_to_urdf(ARM.replace(upper, upper + '<inertial><mass>0</mass></inertial>'))
    assert str(err.value).startswith(
        'model[arm]/link[upper]/inertial/mass: 0 on a dynamic link (on revolute joint shoulder)')


# a shed from a model nobody here knows: its visual is the mesh (turned a quarter),
# its link declares its size in a box and a cylinder collision, as Gazebo models do
SHED = """<model name='shed'><static>1</static><link name='link'>
  <visual name='v'><pose>0 0 0 0 0 1.5707963267948966</pose><geometry><mesh>
    <uri>model://shed_kit/meshes/shed.dae</uri><scale>3 3 3</scale></mesh></geometry></visual>
  <collision name='walls'><pose>0 0 1 0 0 0</pose>
    <geometry><box><size>4 2 2</size></box></geometry></collision>
  <collision name='post'><pose>2.5 0 0.5 0 0 0</pose>
    <geometry><cylinder><radius>0.1</radius><length>1</length></cylinder></geometry></collision>
  <collision name='roof'><geometry><mesh><uri>model://shed_kit/meshes/roof.dae</uri></mesh>
    </geometry></collision>
</link></model>"""


def test_an_unknown_mesh_is_a_box_of_the_size_its_link_collisions_declare():
    w = read_world(world(SHED), model_path=[])
    assert w.notes == [
        "model://shed_kit/meshes/shed.dae is not installed: a 4.60 x 2.00 x 2.00 m box stands "
        "in (the size its link's box, cylinder and sphere collisions declare; seen, its link's "
        "collisions collide), in 1 model: shed",
        'model://shed_kit/meshes/roof.dae is not installed: a 1.00 x 1.00 x 1.00 m box stands '
        'in (the default for a model not in config/gazebo_model_sizes.yaml; seen, not collided '
        'with), in 1 model: shed']
    shed = _models(w)['shed']
    (visual,) = shed.findall('link/visual')
    assert visual.find('geometry/box').get('size') == '4.6 2 2'      # in metres: no <scale>
    xyz = [float(v) for v in visual.find('origin').get('xyz').split()]
    rpy = [float(v) for v in visual.find('origin').get('rpy').split()]
    assert xyz == pytest.approx([0.3, 0, 1]) and rpy == pytest.approx([0, 0, 0], abs=1e-9)
    assert [c.get('name') for c in shed.findall('link/collision')] == ['walls', 'post']


def test_what_gazebo_builds_and_the_simulator_does_not_is_left_out_with_a_line():
    text = world(box_model('ground', '<heightmap><uri>x.png</uri></heightmap>') +
                 "<model name='anchor'><static>1</static></model>" + box_model('m'))
    w = read_world(text, model_path=[])
    assert [m.name for m in w.models] == ['ground', 'm']
    assert w.notes == [
        'world/model[ground]/link[link]/visual[visual]/geometry: a <heightmap> is not simulated '
        'here: left out',
        'world/model[ground]/link[link]/collision[collision]/geometry: a <heightmap> is not '
        'simulated here: left out',
        'world/model[anchor]: no <link>: an empty model, skipped']
    assert _models(w)['ground'].find('link/visual') is None


def test_an_include_sdformat_cannot_find_is_left_out_and_the_world_loads():
    w = read_world(world("<include><uri>model://no_such_thing</uri></include><include/>" +
                         box_model('m')), model_path=[])
    assert [m.name for m in w.models] == ['m']
    assert w.notes == [
        "world/include[model://no_such_thing]: Unable to find uri[model://no_such_thing]: model "
        "'no_such_thing' is not installed (GAZEBO_MODEL_PATH) and has no known size in "
        "config/gazebo_model_sizes.yaml; left out, as sdformat leaves it out",
        "world/include[]: <include> element missing 'uri' attribute (sdformat skips it)"]


def test_a_ball_joint_is_held_fixed_with_a_warning_and_an_empty_spawn_is_refused():
    notes = []
    urdf = model_to_urdf(ARM.replace("type='revolute'", "type='ball'"), notes=notes)
    assert ET.fromstring(urdf).find("joint[@name='shoulder']").get('type') == 'fixed'
    assert notes == ['model[arm]/joint[shoulder]: a ball joint, which Gazebo moves, is held '
                     'fixed here']
    with pytest.raises(SdfError) as err:
        model_to_urdf("<sdf version='1.6'><model name='e'><static>1</static></model></sdf>")
    assert str(err.value) == 'model[e]: the model has no <link> (Gazebo would spawn it empty)'
