"""Assignment profiles: what "works" means, as data (config/grading/*.yaml).

A profile names the world's robot and ball (a first choice: a run whose models are called otherwise
is judged by their roles, :mod:`~exp_assignment2.grading.judge.roles`), the default start commands,
the duration, the limits of a run and its checks (a metric of
:mod:`exp_assignment2.grading.judge.metrics` with thresholds, and the rubric's ``points``, ``zero``
and ``visibility``: :mod:`exp_assignment2.grading.judge.scores`). ``--profile`` takes a profile's
name (``dog``, ``miro``) or the path of a teacher's copy.
"""
import difflib
import os

import yaml

from exp_assignment2.grading.judge.metrics import METRICS
from exp_assignment2.grading.plan import profile_keys
from exp_assignment2.grading.paths import PROFILE_DIR
from exp_assignment2.grading.judge.scores import check_spec

REQUIRED = ('name', 'duration', 'default_commands', 'robot', 'checks')
KEYS = {'name', 'title', 'duration', 'default_commands', 'world_commands', 'delay', 'cpu_per_run',
        'memory_limit_mb', 'process_limit', 'robot', 'ball', 'ball_radius', 'camera',
        'record_topics', 'checks', 'assignment', 'releases', 'release',
        # the course's ball and the behaviours' shared settings (profile_keys.py)
        'base', 'reach', 'home', 'home_radius', 'arena', 'camera_fov',
        'ball_script'}          # a loaded profile's: what ball's script became
CHECK_KEYS = {'name', 'metric', 'min', 'max', 'joint', 'topic', 'points', 'zero',
              'visibility',           # these three: the rubric (grading.scores)
              'home'} | set(profile_keys.NUMBER_KEYS)       # the metrics' own settings
DEFAULTS = {'title': '', 'world_commands': [], 'delay': 5, 'cpu_per_run': 1.0,
            'memory_limit_mb': 3000, 'process_limit': 512, 'ball': None, 'ball_radius': None,
            'camera': None, 'record_topics': [],
            # the names the assignment's package, or the folder holding it, goes by: in a
            # repository of the whole course, the package a run is about (assignment.py)
            'assignment': [],
            # the ROS releases the course allows, and the one a submission that names
            # none is run in first (ros_release.py)
            'releases': ['noetic'], 'release': None,
            # the script the simulator plays for the ball (None: the student's ball node
            # moves it), and the settings every check shares (profile_keys.py)
            'ball_script': None, 'reach': None, 'home': None, 'home_radius': 1.0,
            'arena': None, 'camera_fov': None}


HEAD_METRICS = ('head_turn_near_ball', 'looks_both_ways')     # checks that judge the head
# the course's template as fingerprints, for the similarity report alone (load)
TEMPLATE_PRINTS = 'template_fingerprints'


class ProfileError(Exception):
    """One line naming what is wrong in a profile."""


def _unknown(key, known, where):
    close = difflib.get_close_matches(str(key), sorted(known), n=1)
    return ProfileError('%s: unknown key %r%s' % (where, key,
                                                   ' (did you mean %r?)' % close[0]
                                                   if close else ''))


def available():
    return sorted(f[:-5] for f in os.listdir(PROFILE_DIR) if f.endswith('.yaml'))


def load(name_or_path):
    """The profile (a dict with every key), checked; ProfileError saying why not.
    Without its template fingerprints: the similarity report's alone
    (:func:`template_fingerprints`), never part of what a run is."""
    data, where = _merged(name_or_path)
    if isinstance(data, dict):
        data = {k: v for k, v in data.items() if k != TEMPLATE_PRINTS}
    return check(data, where)


def template_fingerprints(name_or_path):
    """The profile's (or its base's) ``template_fingerprints`` as written, or
    None (:mod:`exp_assignment2.grading.similarity.template_prints` reads it)."""
    data = _merged(name_or_path)[0]
    return data.get(TEMPLATE_PRINTS) if isinstance(data, dict) else None


def _merged(name_or_path):
    """(the profile's raw data over its base's, its file's name)."""
    path, data = _read(name_or_path)
    here = os.path.dirname(path)
    data = profile_keys.merged_with_base(
        data, lambda base: _read(base, here)[1], os.path.basename(path), ProfileError)
    return data, os.path.basename(path)


def _read(name_or_path, here=None):
    """(path, raw data) of a profile by name (config/grading) or file (relative
    to ``here``, a profile's folder, for a ``base``)."""
    path = name_or_path
    if not os.path.sep in name_or_path and not name_or_path.endswith(('.yaml', '.yml')):
        path = os.path.join(PROFILE_DIR, name_or_path + '.yaml')
        if not os.path.isfile(path):
            raise ProfileError('no profile %r (there are: %s)'
                               % (name_or_path, ', '.join(available())))
    elif here and not os.path.isabs(path):
        path = os.path.join(here, path)
    try:
        with open(path) as f:
            return path, yaml.safe_load(f)
    except OSError as exc:
        raise ProfileError('%s: %s' % (path, exc.strerror))
    except yaml.YAMLError as exc:
        raise ProfileError('%s: not YAML: %s' % (path, str(exc).splitlines()[0]))


def check(data, where='profile'):
    if not isinstance(data, dict):
        raise ProfileError('%s: must be a mapping' % where)
    for key in data:
        if key not in KEYS or key == 'base':     # a base is merged before (load)
            raise _unknown(key, KEYS - {'base'}, where)
    for key in REQUIRED:
        if key not in data:
            raise ProfileError('%s: %s is missing' % (where, key))
    profile = dict(DEFAULTS, **data)
    number = (int, float)
    for key in ('duration', 'delay', 'cpu_per_run', 'memory_limit_mb', 'process_limit'):
        if not isinstance(profile[key], number) or isinstance(profile[key], bool) or \
                not 0 < profile[key] < 1e6:
            raise ProfileError('%s: %s: %r is not a positive number' % (where, key, profile[key]))
    if not (isinstance(profile['default_commands'], list) and profile['default_commands']
            and all(isinstance(c, str) for c in profile['default_commands'])):
        raise ProfileError('%s: default_commands: a list of command lines' % where)
    if not (isinstance(profile['assignment'], list)
            and all(isinstance(n, str) and n for n in profile['assignment'])):
        raise ProfileError('%s: assignment: a list of names (the package, its folder)' % where)
    from exp_assignment2.sim.releases import RELEASES
    if not (isinstance(profile['releases'], list) and profile['releases'] and
            all(r in RELEASES for r in profile['releases'])):
        raise ProfileError('%s: releases: %r: a list of ROS releases of %s' % (
            where, profile['releases'], ', '.join(RELEASES)))
    profile['release'] = profile['release'] or profile['releases'][0]
    if profile['release'] not in profile['releases']:
        raise ProfileError('%s: release: %r is not one of its releases (%s)' % (
            where, profile['release'], ', '.join(profile['releases'])))
    if not (isinstance(profile['world_commands'], list)
            and all(isinstance(c, str) for c in profile['world_commands'])):
        raise ProfileError('%s: world_commands: a list of command lines' % where)
    profile['ball'], profile['ball_script'] = profile_keys.parse_ball(
        profile_keys.ball_of(profile), where, ProfileError)
    profile_keys.check_shared(profile, where, ProfileError)
    radius = profile['ball_radius']
    if radius is not None and not (
            isinstance(radius, list) and len(radius) == 2 and all(
                isinstance(v, number) and not isinstance(v, bool) for v in radius)
            and 0 < radius[0] <= radius[1]):
        raise ProfileError('%s: ball_radius: %r is not [min, max] in m, 0 < min <= max'
                           % (where, radius))
    if not isinstance(profile['checks'], list) or not profile['checks']:
        raise ProfileError('%s: checks: a list of checks' % where)
    for i, item in enumerate(profile['checks']):
        here = '%s: checks[%d]' % (where, i)
        if not isinstance(item, dict):
            raise ProfileError('%s: must be a mapping' % here)
        for key in item:
            if key not in CHECK_KEYS:
                raise _unknown(key, CHECK_KEYS, here)
        if item.get('metric') not in METRICS:
            raise ProfileError('%s: metric %r is not one of %s'
                               % (here, item.get('metric'), ', '.join(sorted(METRICS))))
        if 'min' not in item and 'max' not in item:
            raise ProfileError('%s: give a threshold (min or max)' % here)
        profile_keys.check_numbers(item, here, ProfileError)
        check_spec(item, here, ProfileError)
        item.setdefault('name', item['metric'])
    return profile


def with_teacher_roles(profile, roles):
    """The profile of one submission whose robot, head or ball the teacher named
    in grading.yaml (``roles: {robot: rover, head: neck_yaw, ball: orange}``): those are taken as
    named (:mod:`~exp_assignment2.grading.judge.roles`) and the pages say grading.yaml
    named them. ``roles`` None or empty: the profile itself."""
    if not roles:
        return profile
    mine = dict(profile, teacher_named=sorted(roles))
    for key in ('robot', 'ball'):
        if roles.get(key):
            mine[key] = roles[key]
    if roles.get('head'):
        mine['checks'] = [dict(c, joint=roles['head']) if c['metric'] in HEAD_METRICS
                          else c for c in profile['checks']]
    return mine
