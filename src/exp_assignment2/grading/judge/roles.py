"""Which model is the student's robot, which joint its head, which camera it
looks through and which model the ball (no ROS): found by their roles, as a
teacher watching the run finds them, whatever the student called them.

What the simulator said of each model (its joints, sensors, drive plugins and the topics they take,
whether it is a sphere: :mod:`exp_assignment2.sim.model_facts`, read through
:mod:`~exp_assignment2.grading.judge.model_parts`) and what happened to it (commands its drive
took, times a command placed it, the way it went) are in the run's
:class:`~exp_assignment2.grading.judge.metrics.Trace`. From them:

* **the robot**: the model named in the profile, unless nothing drove it
  while another model was driven; else the model that is driven and carries a
  camera, then one that carries a camera, one that is driven, one that went
  somewhere. Static models (a seated person, a kennel) and spheres without a
  camera (the ball) are never it;
* **the head**: the robot's joint whose name holds the profile's ``joint``, if
  it turns the camera (or no joint does); else the revolute joint on the chain
  from the robot's base to the link carrying its camera (a yaw joint first,
  then the nearest the camera);
* **the camera**: the camera that head turns (or the robot's only one): the
  frames of the record that are shown;
* **the ball**: the model the course's script moves, where the simulator
  plays one (its ``scripted`` facts: commands to it are ignored, so it is never
  "moved"); else the model named in the profile, unless it was never moved
  while another sphere was; else, of the other models that cannot be the
  robot, a sphere of the profile's ``ball_radius`` (one that commands moved
  first), then a model commands moved (a ball server's ``cmd_vel``,
  ``set_model_state``, ``set_link_state``).

The teacher may name a submission's roles in grading.yaml
(:func:`~exp_assignment2.grading.plan.profiles.with_teacher_roles`): those are taken as named. A
:class:`Role` that is not found says why, and whether the thing is *absent*
(the world has no robot, the robot no joint but its wheels: a teacher fails
what needs it) or only *untold* (the record cannot say which: the checks
needing it are not run, and the page says so).
"""
import collections

from exp_assignment2.grading.judge import model_parts as parts

MOVED = 0.5        # m a model with no drive must go to count as a robot that moved


class Role(collections.namedtuple('Role', 'name why absent')):
    """``name`` of the model, joint or camera (None: not found), ``why`` it is
    that one (or why none is), ``absent``: not found because the world has none."""

    def __new__(cls, name, why, absent=False):
        return super(Role, cls).__new__(cls, name, why, bool(absent))


NO_ROLE = Role(None, 'the profile judges none')


class Roles(object):
    """The run's robot, head, camera and ball (:class:`Role` each)."""

    KEYS = ('robot', 'head', 'camera', 'ball')

    def __init__(self, robot=NO_ROLE, head=NO_ROLE, camera=NO_ROLE, ball=NO_ROLE, namespace=''):
        self.robot, self.head, self.camera, self.ball = robot, head, camera, ball
        self.namespace = namespace         # the robot's: where its relative topics are

    def to_dict(self):
        out = {key: getattr(self, key)._asdict() for key in self.KEYS}
        out['namespace'] = self.namespace
        return out

    @classmethod
    def from_dict(cls, data):
        data = data if isinstance(data, dict) else {}
        found = {key: Role(data[key].get('name'), data[key].get('why') or '',
                           data[key].get('absent')) for key in cls.KEYS
                 if isinstance(data.get(key), dict)}
        return cls(namespace=data.get('namespace') or '', **found)


def _code(name):
    return '`%s`' % name


def _teacher(profile, role):
    return role in (profile.get('teacher_named') or ())


def _nothing_described(trace, what):
    """The role when no model fits: untold where the simulator left some model
    undescribed (an older record, a lost line), else absent."""
    seen = set(name for state in trace.states for name in state['models'])
    undescribed = sorted(seen - set(trace.models))
    if undescribed:
        return Role(None, 'the simulator did not describe %s: which is the %s cannot be told'
                    % (', '.join(map(_code, undescribed)), what))
    return None


def _robot_like(trace, facts):
    """It may be the robot: not static, and a camera, a drive (not a sphere's) or a way gone."""
    if facts.get('static'):
        return False
    if parts.cameras(facts):
        return True
    return facts.get('sphere') is None and (bool(parts.drive_topics(facts)) or
                                            trace.travelled(facts['name']) >= MOVED)


def find_robot(trace, profile):
    """The robot's :class:`Role`: see the module docstring."""
    named = profile.get('robot')
    fed = lambda name: trace.counter('fed', name)      # noqa: E731
    candidates = [f for f in trace.models.values() if _robot_like(trace, f)]
    if named and trace.seen(named):
        driven = [f['name'] for f in candidates if fed(f['name']) and f['name'] != named]
        if _teacher(profile, 'robot') or fed(named) or not driven:
            return Role(named, '%s, as %s' % (_code(named), 'grading.yaml names it for this '
                                              'submission' if _teacher(profile, 'robot')
                                              else 'the profile names it'))
    elif named and _teacher(profile, 'robot'):
        return Role(None, 'grading.yaml names the robot %s, which the run does not have'
                    % _code(named))
    if not candidates:
        return _nothing_described(trace, 'robot') or Role(
            None, 'no robot in the world: no model %s, none with a drive or a camera, none '
                  'that went anywhere (models: %s)' % (_code(named), ', '.join(
                      map(_code, sorted(trace.models))) or 'none'), absent=True)

    def rank(facts):
        camera = bool(parts.cameras(facts))
        return (camera and fed(facts['name']) > 0, camera, fed(facts['name']) > 0,
                fed(facts['name']), trace.travelled(facts['name']))
    best = max(sorted(candidates, key=lambda f: f['name']), key=rank)
    reasons = []
    if fed(best['name']):
        reasons.append('driven%s (%d commands)' % (
            ''.join(' through ' + t for t in parts.drive_topics(best)[:1]), fed(best['name'])))
    if parts.cameras(best):
        reasons.append('carries camera %s' % ', '.join(_code(c[0]) for c in parts.cameras(best)))
    if not reasons:
        reasons.append('has a drive on %s, though nothing drove it' % ', '.join(
            parts.drive_topics(best)) if parts.drive_topics(best) else
            'went %.1f m' % trace.travelled(best['name']))
    there = ('%s is there, but nothing drove it' % _code(named) if named and trace.seen(named)
             else 'no model %s' % _code(named))
    return Role(best['name'], '%s: %s (%s)' % (_code(best['name']), ' and '.join(reasons), there))


def _camera_role(cameras, tag):
    served = [c for c in cameras if c[2]]
    chosen = next((c for c in served if c[2] == tag), served[0] if len(served) == 1 else None)
    if chosen is None:
        return Role(None, 'no camera of the robot is drawn here' if not served else
                    'the robot has %d cameras, none on its head' % len(served))
    return Role(chosen[2], '%s on %s' % (_code(chosen[0]), _code(chosen[1])))


def _named_head(trace, robot, facts, fragment, teacher):
    """(head, camera) the name gives, or None to find the head by its role."""
    cameras = parts.cameras(facts)
    moving = trace.joint_names(robot)
    if teacher:
        if fragment in moving:
            on = next((c[2] for c in cameras if fragment in parts.chain(facts, c[1])), None)
            return (Role(fragment, '%s, as grading.yaml names it for this submission'
                         % _code(fragment)), _camera_role(cameras, on))
        return (Role(None, 'grading.yaml names the head %s; %s has no such moving joint '
                           '(it has %s)' % (_code(fragment), _code(robot), ', '.join(
                               map(_code, moving)) or 'none')), _camera_role(cameras, None))
    matches = [j for j in moving if fragment and fragment in j]
    turning = {j: c[2] for c in cameras for j in parts.turning_on_chain(facts, c[1])}
    if turning:        # a name off the camera's chain (head_light) is not the head
        matches = [j for j in matches if j in turning]
    if not matches:
        return None
    matches.sort(key=lambda j: (j not in turning, not parts.is_yaw(facts, j), j))
    return (Role(matches[0], '%s, named like %s as the profile asks' % (
        _code(matches[0]), _code(fragment))), _camera_role(cameras, turning.get(matches[0])))


def find_head(trace, robot, fragment, teacher=False):
    """(head, camera) of the robot: see the module docstring."""
    if robot.name is None:
        return Role(None, 'no robot: ' + robot.why, robot.absent), NO_ROLE
    facts = trace.models.get(robot.name)
    named = _named_head(trace, robot.name, facts, fragment, teacher)
    if named is not None:
        return named
    if not facts:
        return (Role(None, 'the simulator did not describe %s and none of its joints is named '
                           'like %s: which is the head cannot be told' % (
                               _code(robot.name), _code(fragment))), NO_ROLE)
    cameras = parts.cameras(facts)
    for name, link, tag in cameras:
        turning = parts.turning_on_chain(facts, link)
        if turning:
            joint = ([j for j in turning if parts.is_yaw(facts, j)] or turning)[0]
            return (Role(joint, '%s, the joint that turns camera %s (on %s)' % (
                _code(joint), _code(name), _code(link))), _camera_role(cameras, tag))
    others = [j for j, f in sorted(parts.joints(facts).items())
              if f.get('type') == 'revolute' and j not in parts.wheels(facts)]
    camera = _camera_role(cameras, None)
    if not cameras:
        if others:
            return (Role(None, '%s carries no camera the simulator knows, and has joints %s: '
                               'which is its head cannot be told' % (
                                   _code(robot.name), ', '.join(map(_code, others)))), camera)
        return (Role(None, '%s has no camera and no joint but its wheels: it has no head'
                     % _code(robot.name), absent=True), camera)
    fixed = ', '.join('%s on %s' % (_code(n), _code(l)) for n, l, _ in cameras)
    if others:
        return (Role(None, 'no joint turns camera %s; %s do not carry it: which is the head '
                           'cannot be told' % (fixed, ', '.join(map(_code, others)))), camera)
    return (Role(None, 'camera %s is fixed and no joint but the wheels moves: %s has no head'
                 % (fixed, _code(robot.name)), absent=True), camera)


def _radius_fits(radius, bounds):
    return radius is not None and (not bounds or bounds[0] <= radius <= bounds[1])


def find_ball(trace, profile, robot):
    """The ball's :class:`Role`: see the module docstring."""
    named = profile.get('ball')
    if not named:
        return NO_ROLE
    bounds = profile.get('ball_radius')
    moved = lambda name: trace.counter('fed', name) + trace.counter('placed', name)  # noqa: E731
    others = [f for f in trace.models.values() if f['name'] != robot.name and not (
        parts.cameras(f) or (parts.drive_topics(f) and f.get('sphere') is None))]
    spheres = [f for f in others if _radius_fits(f.get('sphere'), bounds)]
    held = sorted(f['name'] for f in others if f.get('scripted'))
    if held and not _teacher(profile, 'ball'):
        # the course's script moves it: its commands were ignored, so nothing "moved" it
        chosen = named if named in held else held[0]
        seed = (trace.models[chosen]['scripted'] or {}).get('seed')
        return Role(chosen, '%s: the ball the course\'s script moves (%s)%s' % (
            _code(chosen), 'seed %s' % seed if seed is not None else 'legs given by hand',
            '' if chosen == named else ' (no model %s is)' % _code(named) if named else ''))
    if named and trace.seen(named):
        rivals = [f for f in spheres if moved(f['name']) and f['name'] != named]
        if _teacher(profile, 'ball') or moved(named) or not rivals:
            return Role(named, '%s, as %s' % (_code(named), 'grading.yaml names it for this '
                                              'submission' if _teacher(profile, 'ball')
                                              else 'the profile names it'))
    elif _teacher(profile, 'ball'):
        return Role(None, 'grading.yaml names the ball %s, which the run does not have'
                    % _code(named))
    fits = spheres or [f for f in others if moved(f['name'])]
    if not fits:
        return _nothing_described(trace, 'ball') or Role(
            None, 'no ball in the world: no model %s, no sphere%s, none that a command moved'
                  % (_code(named), ' of radius %g to %g m' % tuple(bounds) if bounds else ''),
            absent=True)
    best = max(sorted(fits, key=lambda f: f['name']), key=lambda f: (
        moved(f['name']), trace.travelled(f['name'])))
    reasons = []
    if best.get('sphere') is not None:
        reasons.append('a sphere of radius %g m' % best['sphere'])
    if trace.counter('fed', best['name']):
        reasons.append('moved through %s (%d commands)' % (
            ', '.join(parts.drive_topics(best)), trace.counter('fed', best['name'])))
    if trace.counter('placed', best['name']):
        reasons.append('placed %d times by set_model_state/set_link_state'
                       % trace.counter('placed', best['name']))
    there = ('%s is there, but nothing moved it' % _code(named) if trace.seen(named)
             else 'no model %s' % _code(named))
    return Role(best['name'], '%s: %s (%s)' % (_code(best['name']), ', '.join(reasons), there))


def head_fragment(profile):
    """The part of the head joint's name the profile's checks give (default ``head``)."""
    return next((c.get('joint') for c in profile['checks'] if c.get('joint')), 'head')


def find(trace, profile):
    """The run's :class:`Roles`."""
    robot = find_robot(trace, profile)
    head, camera = find_head(trace, robot, head_fragment(profile), _teacher(profile, 'head'))
    chosen = profile.get('camera')
    if chosen and chosen in trace.models:        # the profile's choice of whose camera to show
        served = [c for c in parts.cameras(trace.models[chosen]) if c[2]]
        if served:
            camera = Role(served[0][2], '%s on %s, as the profile asks' % (
                _code(served[0][0]), _code(chosen)))
    namespace = (trace.models.get(robot.name) or {}).get('namespace') or ''
    return Roles(robot=robot, head=head, camera=camera, ball=find_ball(trace, profile, robot),
                 namespace=namespace)


def of_run(run, trace, profile):
    """The roles a run's verdict judged (its record's ``roles``); found again in
    the trace for a record made before roles were kept."""
    if run.get('roles'):
        return Roles.from_dict(run['roles'])
    return find(trace, profile)
