"""Which model is the student's robot, which joint its head, which camera it
looks through and which model the ball (no ROS): found by their roles, as a
teacher watching the run finds them, whatever the student called them.

What the simulator said of each model (its joints, sensors, drive plugins and
the topics they take, whether it is a sphere: :mod:`exp_assignment2.sim.model_facts`)
and what happened to it (commands its drive took, times a command placed it,
the way it went) are in the run's :class:`~.metrics.Trace`. From them:

* **the robot**: the model named in the profile, if the run has one; else the
  model that is driven (its drive plugin took commands) and carries a camera,
  then one that carries a camera, then one that is driven. A model with
  neither (a seated person, a kennel) is never it, nor is a sphere without a
  camera (the ball);
* **the head**: the robot's joint whose name holds the profile's ``joint`` (a
  first choice); else the revolute joint on the chain from the robot's base to
  the link carrying its camera (a yaw joint first, then the nearest the camera);
* **the camera**: the camera that head turns (or the robot's only one): the
  frames of the record that are shown;
* **the ball**: the model named in the profile, if the run has one; else the
  model (not the robot) that commands moved (a ball server's ``cmd_vel``,
  ``set_model_state``, ``set_link_state``), then a sphere of the profile's
  ``ball_radius``.

A :class:`Role` that is not found says why, and says whether the thing is
*absent* (the world has no robot, the robot no joint but its wheels: a teacher
would fail what needs it) or only *untold* (the record cannot say which: the
checks needing it are not run, and the page says so).
"""
import collections

TURNING = ('revolute', 'continuous')
YAW = 0.9          # |z| of a joint's unit axis (root frame) for a joint that turns the head left/right


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
        data = data or {}
        return cls(namespace=data.get('namespace') or '', **{
            key: Role(**data[key]) for key in cls.KEYS if isinstance(data.get(key), dict)})

    @classmethod
    def named(cls, profile, joint=None):
        """The profile's names taken as they are (a record the simulator described
        nothing in: names are all there is)."""
        return cls(robot=Role(profile.get('robot'), 'named in the profile'),
                   head=Role(None, 'the profile names a part of the joint\'s name only')
                   if joint is None else Role(joint, 'named in the profile'),
                   ball=Role(profile.get('ball'), 'named in the profile') if profile.get('ball')
                   else NO_ROLE)


def _code(name):
    return '`%s`' % name


def _named_by(profile, role):
    """Who named a role: the teacher for this submission, or the profile."""
    return 'grading.yaml names it for this submission' \
        if role in (profile.get('teacher_named') or ()) else 'the profile names it'


def named_by_teacher(profile, roles):
    """The profile of one submission whose robot, head or ball the teacher named
    in grading.yaml (``roles: {robot: rover, head: neck_yaw, ball: orange}``):
    those names come first, as the profile's would, and the pages say who
    named them. ``roles`` None or empty: the profile itself."""
    if not roles:
        return profile
    mine = dict(profile, teacher_named=sorted(roles))
    for key in ('robot', 'ball'):
        if roles.get(key):
            mine[key] = roles[key]
    if roles.get('head'):
        mine['checks'] = [dict(c, joint=roles['head']) if c['metric'] == 'head_turn_near_ball'
                          else c for c in profile['checks']]
    return mine


def _cameras(facts):
    """[(sensor name, link, frame tag or None)] of a model's camera sensors; the
    tag names its frames in the record (``model/cameraName``) when a plugin
    here serves it."""
    served = {p['sensor']['link']: p.get('camera') for p in facts.get('plugins') or ()
              if p.get('sensor') and p.get('camera')}
    return [(s['name'], s['link'], '%s/%s' % (facts['name'], served[s['link']])
             if served.get(s['link']) else None)
            for s in facts.get('sensors') or () if 'camera' in (s.get('type') or '')]


def _drive_topics(facts):
    return [p['command'] for p in facts.get('plugins') or () if p.get('drive')]


def _wheels(facts):
    return {j for p in facts.get('plugins') or () if p.get('drive') for j in p.get('joints') or ()}


def _yaw(facts, joint):
    """The joint turns about the vertical (left and right, as a head looks around)."""
    axis = ((facts or {}).get('joints', {}).get(joint) or {}).get('axis') or [0, 0, 0]
    return abs(axis[2]) > YAW


def _chain(facts, link):
    """Joint names from ``link`` up to the root, nearest first."""
    parent_of = {j['child']: (name, j['parent']) for name, j in facts['joints'].items()}
    chain, seen = [], set()
    while link in parent_of and link not in seen:
        seen.add(link)
        name, link = parent_of[link]
        chain.append(name)
    return chain


def find_robot(trace, profile):
    named = profile.get('robot')
    if named and trace.seen(named):
        return Role(named, '%s, as %s' % (_code(named), _named_by(profile, 'robot')))
    candidates = [f for f in trace.models.values() if not f.get('static') and (
        _cameras(f) or (_drive_topics(f) and f.get('sphere') is None))]
    if not candidates:
        if not trace.models:
            return Role(None, 'no model %s in the ground truth, and the simulator described no '
                              'model: the robot cannot be told' % _code(named))
        return Role(None, 'no robot in the world: no model %s, none with a drive or a camera '
                          '(models: %s)' % (_code(named), ', '.join(
                              _code(n) for n in sorted(trace.models))), absent=True)

    def rank(facts):
        fed, camera = trace.counter('fed', facts['name']), bool(_cameras(facts))
        return (camera and fed > 0, camera, fed > 0, fed, trace.travelled(facts['name']))
    best = max(sorted(candidates, key=lambda f: f['name']), key=rank)
    fed = trace.counter('fed', best['name'])
    reasons = []
    if fed:
        reasons.append('driven through %s (%d commands)' % (
            ', '.join(_drive_topics(best)), fed))
    cameras = _cameras(best)
    if cameras:
        reasons.append('carries camera %s' % ', '.join(_code(c[0]) for c in cameras))
    if not reasons:
        reasons.append('has a drive plugin on %s, though nothing drove it'
                       % ', '.join(_drive_topics(best)))
    return Role(best['name'], '%s: %s (no model %s)' % (
        _code(best['name']), ' and '.join(reasons), _code(named)))


def find_head(trace, robot, fragment, named_by='the profile asks'):
    """(head, camera) of the robot."""
    if robot.name is None:
        return Role(None, 'no robot: ' + robot.why, robot.absent), NO_ROLE
    facts = trace.models.get(robot.name)
    cameras = _cameras(facts) if facts else []
    moving = trace.joint_names(robot.name)
    if fragment:
        named = [j for j in moving if fragment in j]
        if named:
            # head_pan and head_tilt: the one turning the camera, about z, first
            on_camera = {j: c[2] for c in cameras for j in _chain(facts, c[1])}
            named.sort(key=lambda j: (j not in on_camera, not _yaw(facts, j), j))
            return (Role(named[0], '%s, named like %s as %s' % (
                _code(named[0]), _code(fragment), named_by)),
                _camera_role(cameras, on_camera.get(named[0])))
    if not facts:
        return (Role(None, 'the simulator did not describe %s and none of its joints is named '
                           'like %s: which is the head cannot be told' % (
                               _code(robot.name), _code(fragment))), NO_ROLE)
    for name, link, tag in cameras:
        turning = [j for j in _chain(facts, link) if facts['joints'][j]['type'] in TURNING]
        if turning:
            joint = ([j for j in turning if _yaw(facts, j)] or turning)[0]
            return (Role(joint, '%s, the joint that turns camera %s (on %s)' % (
                _code(joint), _code(name), _code(link))), _camera_role(cameras, tag))
    others = [j for j, f in sorted(facts['joints'].items())
              if f['type'] in TURNING and j not in _wheels(facts)]
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


def _camera_role(cameras, tag):
    served = [c for c in cameras if c[2]]
    chosen = next((c for c in served if c[2] == tag), served[0] if len(served) == 1 else None)
    if chosen is None:
        return Role(None, 'no camera of the robot is drawn here' if not served else
                    'the robot has %d cameras, none on its head' % len(served))
    return Role(chosen[2], '%s on %s' % (_code(chosen[0]), _code(chosen[1])))


def _in(radius, bounds):
    return radius is not None and (not bounds or bounds[0] <= radius <= bounds[1])


def find_ball(trace, profile, robot):
    named = profile.get('ball')
    if not named:
        return NO_ROLE
    if trace.seen(named):
        return Role(named, '%s, as %s' % (_code(named), _named_by(profile, 'ball')))
    bounds = profile.get('ball_radius')
    others = [f for f in trace.models.values() if f['name'] != robot.name]   # a ball may be static

    def moved(facts):
        return trace.counter('fed', facts['name']) + trace.counter('placed', facts['name'])

    fits = [f for f in others if moved(f) or _in(f.get('sphere'), bounds)]
    if not fits:
        if not trace.models:
            return Role(None, 'no model %s in the ground truth, and the simulator described no '
                              'model: the ball cannot be told' % _code(named))
        return Role(None, 'no ball in the world: no model %s, none that a command moved, no '
                          'sphere%s' % (_code(named), ' of radius %g to %g m' % tuple(bounds)
                                        if bounds else ''), absent=True)
    best = max(sorted(fits, key=lambda f: f['name']), key=lambda f: (
        moved(f) > 0, _in(f.get('sphere'), bounds), moved(f), trace.travelled(f['name'])))
    reasons = []
    if trace.counter('fed', best['name']):
        reasons.append('moved through %s (%d commands)' % (
            ', '.join(_drive_topics(best)), trace.counter('fed', best['name'])))
    if trace.counter('placed', best['name']):
        reasons.append('placed %d times by set_model_state/set_link_state'
                       % trace.counter('placed', best['name']))
    if best.get('sphere') is not None:
        reasons.append('a sphere of radius %g m' % best['sphere'])
    return Role(best['name'], '%s: %s (no model %s)' % (
        _code(best['name']), ', '.join(reasons), _code(named)))


def head_fragment(profile):
    """The part of the head joint's name the profile's checks give (default ``head``)."""
    return next((c.get('joint') for c in profile['checks'] if c.get('joint')), 'head')


def find(trace, profile):
    """The run's :class:`Roles`."""
    robot = find_robot(trace, profile)
    head, camera = find_head(trace, robot, head_fragment(profile),
                             'grading.yaml asks for this submission'
                             if 'head' in (profile.get('teacher_named') or ()) else
                             'the profile asks')
    chosen = profile.get('camera')
    if chosen and chosen in trace.models:        # the profile's choice of whose camera to show
        served = [c for c in _cameras(trace.models[chosen]) if c[2]]
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
