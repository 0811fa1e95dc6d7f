"""What a model's facts say of its parts (no ROS): its cameras, its drives and
wheels, the joints from a link down to its root, which way a joint turns.

The facts are what the simulator sent of a spawned model
(:func:`exp_assignment2.sim.model_facts.describe`); a record may come from an
older simulator or a hostile world, so every key is read as optional.
"""
TURNING = ('revolute', 'continuous')
# Gazebo's sensor types that look: a camera, a Kinect's depth camera, and the rest
CAMERA_TYPES = ('camera', 'depth', 'multicamera', 'wideanglecamera')
YAW = 0.9          # |z| of a joint's unit axis (root frame) for a joint that turns left/right


def joints(facts):
    """{name: {type, parent, child, axis}} of the model (empty when unknown)."""
    found = (facts or {}).get('joints')
    return found if isinstance(found, dict) else {}


def cameras(facts):
    """[(sensor name, link, frame tag or None)] of a model's camera sensors; the
    tag names its frames in the record (``model/cameraName``) when a plugin
    here draws it."""
    facts = facts or {}
    served = {}
    for plugin in facts.get('plugins') or ():
        sensor = plugin.get('sensor') or {}
        if sensor.get('link') and plugin.get('camera'):
            served[sensor['link']] = plugin['camera']
    out = []
    for sensor in facts.get('sensors') or ():
        kind = sensor.get('type') or ''
        if kind in CAMERA_TYPES or 'camera' in kind:
            link = sensor.get('link')
            out.append((sensor.get('name') or '?', link, '%s/%s' % (facts.get('name'), served[link])
                        if served.get(link) else None))
    return out


def drive_topics(facts):
    """The topics the model's drive plugins take velocity commands on."""
    return [p.get('command') or '?' for p in (facts or {}).get('plugins') or () if p.get('drive')]


def wheels(facts):
    """Joints that roll the model: its drives' and every continuous one (casters)."""
    named = {j for p in (facts or {}).get('plugins') or () if p.get('drive')
             for j in p.get('joints') or ()}
    return named | {name for name, j in joints(facts).items() if j.get('type') == 'continuous'}


def is_yaw(facts, joint):
    """The joint turns about the vertical (left and right, as a head looks around)."""
    axis = (joints(facts).get(joint) or {}).get('axis') or [0, 0, 0]
    return len(axis) == 3 and abs(axis[2]) > YAW


def chain(facts, link):
    """Joint names from ``link`` down to the root, nearest first (a cycle ends it)."""
    parent_of = {j.get('child'): (name, j.get('parent')) for name, j in joints(facts).items()}
    found, seen = [], set()
    while link in parent_of and link not in seen:
        seen.add(link)
        name, link = parent_of[link]
        found.append(name)
    return found


def turning_on_chain(facts, link):
    """The joints that turn ``link`` (revolute or continuous on its chain), nearest first."""
    return [j for j in chain(facts, link) if (joints(facts).get(j) or {}).get('type') in TURNING]
