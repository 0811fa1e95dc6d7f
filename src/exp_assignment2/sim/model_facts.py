"""What a model is, as a grader needs it to tell which model plays which role
(no ROS).

Students rename things: the robot may be spawned as ``robot2`` in its own
namespace, the head may turn on ``camera_joint``, the ball may be called
anything. A teacher watching a run looks at the robot that is driven, the
joint that turns its camera and the sphere the ball server moves, whatever
their names. The simulator knows each of those facts from the model's URDF
and its ``<gazebo>`` plugins; :func:`describe` writes them down as plain
data, sent once per spawned model in the ground truth
(:mod:`.ground_truth`). Deciding the roles from them is the grader's
business (:mod:`exp_assignment2.grading.judge.roles`).
"""

MOVING_JOINTS = ('revolute', 'continuous', 'prismatic')


def _rounded(values, digits=3):
    return [round(float(v), digits) for v in values]


def _joints(urdf):
    """{name: {type, parent, child, axis}}; ``axis`` (a moving joint's, in the
    root link's frame with every joint at zero) tells a yaw joint from a tilt."""
    out = {}
    for name, joint in urdf.joints.items():
        axis = None
        if joint.type in MOVING_JOINTS:
            axis = _rounded(urdf.joint_axis_in_root(name)[1])
        out[name] = {'type': joint.type, 'parent': joint.parent, 'child': joint.child,
                     'axis': axis}
    return out


def sphere(urdf):
    """(radius, rgba) when the model is drawn as one sphere (a ball), else None."""
    visuals = [v for link in urdf.links.values() for v in link.visuals]
    if len(visuals) != 1 or visuals[0].kind != 'sphere':
        return None
    return round(float(visuals[0].params['radius']), 4), _rounded(visuals[0].rgba)


def _sensors(urdf):
    """Every ``<sensor>`` declared, whether a plugin here serves it or not: a
    camera's link is where the robot looks from, whatever publishes it."""
    seen, out = set(), []
    for decl in urdf.gazebo.plugins:
        sensor = decl.sensor
        if sensor is not None and (sensor.name, sensor.link) not in seen:
            seen.add((sensor.name, sensor.link))
            out.append({'type': sensor.type, 'name': sensor.name, 'link': sensor.link})
    return out


def describe(model, plugins, ros_release=None):
    """The facts of a spawned :class:`~.model.Model` and its loaded plugins
    (each plugin's :meth:`~.plugins.base.Plugin.facts`), as JSON-ready data;
    ``ros_release``: the release whose Gazebo plugins ran it (its name);
    ``scripted``: the ball script moving it (seed, start, duration, legs:
    :mod:`.scripted_ball`), None when it is not held by one."""
    urdf = model.urdf
    ball = sphere(urdf)
    return {'name': model.name, 'namespace': model.namespace, 'ros_release': ros_release,
            'root': urdf.root,
            'static': bool(model.static), 'kinematic': bool(model.kinematic),
            'links': list(urdf.links), 'joints': _joints(urdf),
            'sphere': ball[0] if ball else None,
            'colour': ball[1] if ball else None,
            'sensors': _sensors(urdf),
            'plugins': [plugin.facts() for plugin in plugins],
            'scripted': model.script}
