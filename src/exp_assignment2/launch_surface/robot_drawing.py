"""What gzclient draws of the robots: each model spawned from a URDF that is on
the parameter server (``robot_description``, ``/robot/robot_description``,
``ball_description``, ...) drawn from that URDF, each link's visuals locked to
the link's TF frame (``gazebo/<model>/<link>``, which gzclient broadcasts from
``/gazebo/link_states``), so the links move as the simulator moves them.

:func:`find_descriptions` reads the URDFs of the parameter server (names
ending in ``description``); :func:`match` pairs a model with the URDF whose
links are the model's; :func:`robot_markers` is the markers of one model.
Static models are not drawn here: the simulator's ``world_markers`` has them.
"""
from visualization_msgs.msg import Marker

from exp_assignment2.launch_surface import viewer
from exp_assignment2.ros.world_markers import KINDS, shape_marker
from exp_assignment2.sim import urdf as urdf_reader
from exp_assignment2.sim.world_shapes import Shape


def find_descriptions(names, get):
    """{parameter: UrdfModel} of the parameters among ``names`` whose name ends
    in ``description`` and whose value (``get(name)``) is a URDF that reads."""
    found = {}
    for name in names:
        if not name.rstrip('/').endswith('description'):
            continue
        try:
            text = get(name)
            if isinstance(text, str) and '<robot' in text:
                found[name] = urdf_reader.parse(text)
        except Exception:       # not a URDF this reader takes: not drawn
            continue
    return found


def match(model_links, descriptions):
    """The (parameter, UrdfModel) whose links are exactly ``model_links``, or None;
    the shortest parameter name first (``/robot_description`` before a copy)."""
    for name in sorted(descriptions, key=lambda n: (len(n), n)):
        if set(descriptions[name].links) == set(model_links):
            return name, descriptions[name]
    return None


def robot_markers(model, urdf, first_id=0):
    """Markers of ``urdf``'s visuals for model ``model``, locked to its link frames."""
    markers = []
    if urdf.gazebo.static:
        return markers
    for link, visuals in urdf.visuals.items():
        frame = viewer.frame_name('%s::%s' % (model, link))
        for visual in visuals:
            if visual.kind not in KINDS or (visual.kind == 'mesh' and
                                            not visual.params.get('filename')):
                continue
            shape = Shape(model, link, visual.kind, visual.params, visual.origin, visual.rgba)
            marker = shape_marker(shape, frame, first_id + len(markers))
            marker.frame_locked = True
            markers.append(marker)
    return markers


def delete_all():
    """The marker that clears what was drawn before."""
    return Marker(action=Marker.DELETEALL)
