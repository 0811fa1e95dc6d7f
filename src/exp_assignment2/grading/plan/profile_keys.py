"""A profile's keys for the assignment's behaviours and the course's ball (no
ROS; docs/grading.md, "What works means: profiles"), checked here and read by
:mod:`~exp_assignment2.grading.plan.profiles`:

* ``ball``: the ball model's name (``ball: ball``, as before), or a mapping
  ``{name: ball, script: ...}`` whose ``script`` has the simulator play the
  course's ball (:mod:`exp_assignment2.sim.ball_script`) the same way for every
  submission, whatever its own ball node does: ``true`` or ``{}`` (each run's
  seed: ``--seed``, ``--episodes``), ``{seed: 3}`` (episodes 3, 4, ...) or
  ``{seeds: [3, 8, 13], hidden: [13]}`` (a hidden seed's episode is on the
  teacher's pages only), and optionally ``model:`` (the model it moves; default:
  the sphere the simulator finds by its role). Loaded, ``ball`` is the name and
  ``ball_script`` the script (None: the student's own ball node moves it);
* ``base``: a profile (name or file) whose keys this one takes, its own over them;
* ``reach``, ``home``, ``home_radius``, ``arena``, ``camera_fov``: settings
  every check takes unless it gives its own (:data:`SHARED`): one distance for
  the reach and the head, the dog's home, where a ball is "there", the camera's
  field of view where the simulator did not say it.
"""
import numbers

SHARED = ('reach', 'home', 'home_radius', 'arena', 'camera_fov')
SCRIPT_KEYS = ('seed', 'seeds', 'hidden', 'model')
# check keys that are a number (metrics.py and behaviours.py read them)
NUMBER_KEYS = ('min', 'max', 'reach', 'tolerance', 'occasion', 'spacing', 'gap', 'follow',
               'moving', 'angle', 'stop', 'near', 'leave', 'own', 'closing', 'radius', 'grace',
               'rest', 'look', 'window', 'settle', 'unseen', 'per')


def _number(value):
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _seed(value):
    return isinstance(value, int) and not isinstance(value, bool) and value >= 0


def parse_ball(value, where, error):
    """(name or None, script or None) of a profile's ``ball``; ``error`` (one line) if wrong.
    The script is ``{'seeds': [int] or None (each run's own seed), 'hidden': [int],
    'model': str or None}``."""
    if value is None or isinstance(value, str):
        return value, None
    if not isinstance(value, dict):
        raise error('%s: ball: %r is neither a model\'s name nor {name: ..., script: ...}'
                    % (where, value))
    unknown = sorted(set(value) - {'name', 'script'})
    if unknown:
        raise error('%s: ball: unknown key %r (known: name, script)' % (where, unknown[0]))
    name = value.get('name')
    if name is not None and not (isinstance(name, str) and name.strip()):
        raise error('%s: ball: name: %r is not a model\'s name' % (where, name))
    script = value.get('script')
    if script is None or script is False:
        return name, None
    if script is True:
        return name, {'seeds': None, 'hidden': [], 'model': None}
    if not isinstance(script, dict):
        raise error('%s: ball: script: %r: give true, {seed: 3} or {seeds: [3, 8]}'
                    % (where, script))
    unknown = sorted(set(script) - set(SCRIPT_KEYS))
    if unknown:
        raise error('%s: ball: script: unknown key %r (known: %s)'
                    % (where, unknown[0], ', '.join(SCRIPT_KEYS)))
    if 'seed' in script and 'seeds' in script:
        raise error('%s: ball: script: give seed or seeds, not both' % where)
    seeds = [script['seed']] if 'seed' in script else script.get('seeds')
    if seeds is not None and not (isinstance(seeds, list) and seeds and all(map(_seed, seeds))):
        raise error('%s: ball: script: %r: seeds are whole numbers >= 0' % (where, seeds))
    hidden = script.get('hidden') or []
    if not (isinstance(hidden, list) and all(h in (seeds or []) for h in hidden)):
        raise error('%s: ball: script: hidden: %r: a list of the script\'s seeds'
                    % (where, hidden))
    model = script.get('model')
    if model is not None and not (isinstance(model, str) and model.strip()):
        raise error('%s: ball: script: model: %r is not a model\'s name' % (where, model))
    return name, {'seeds': seeds, 'hidden': list(hidden), 'model': model}


def ball_of(profile):
    """A profile's ``ball`` as written, from a loaded one too (its ``ball_script``)."""
    script = profile.get('ball_script')
    if script is None or not isinstance(script, dict):
        return profile.get('ball') if script is None else {'name': profile.get('ball'),
                                                           'script': script}
    again = {k: v for k, v in script.items() if v not in (None, [])}
    return {'name': profile.get('ball'), 'script': again or True}


def check_shared(profile, where, error):
    """``error`` (one line) if a setting of :data:`SHARED` is wrong."""
    if profile.get('reach') is not None and not (_number(profile['reach'])
                                                 and profile['reach'] > 0):
        raise error('%s: reach: %r is not a positive distance in m' % (where, profile['reach']))
    home = profile.get('home')
    if home is not None and not (isinstance(home, list) and len(home) == 2
                                 and all(map(_number, home))):
        raise error('%s: home: %r is not [x, y] in m (null: the place it rests at)'
                    % (where, home))
    for key in ('home_radius', 'camera_fov'):
        if profile.get(key) is not None and not (_number(profile[key]) and profile[key] > 0):
            raise error('%s: %s: %r is not a positive number' % (where, key, profile[key]))
    arena = profile.get('arena')
    if arena is not None and not (isinstance(arena, list) and len(arena) == 4 and all(
            map(_number, arena)) and arena[0] < arena[1] and arena[2] < arena[3]):
        raise error('%s: arena: %r is not [x_min, x_max, y_min, y_max] in m' % (where, arena))


def check_numbers(item, here, error):
    """``error`` if a check's numeric key is not a number, or its ``home`` not [x, y]."""
    for key in NUMBER_KEYS:
        if key in item and not _number(item[key]):
            raise error('%s: %s: %r is not a number' % (here, key, item[key]))
    if item.get('home') is not None:
        check_shared({'home': item['home']}, here, error)


def with_shared(check, profile):
    """The check's settings: its own, else the profile's :data:`SHARED` ones."""
    shared = {k: profile.get(k) for k in SHARED if profile.get(k) is not None}
    return dict(shared, **check)


def merged_with_base(data, read, where, error, seen=()):
    """``data`` over the profile its ``base`` names (read by ``read(name)``, raw),
    itself over its own base; a cycle is ``error``."""
    if not isinstance(data, dict) or 'base' not in data:
        return data
    base = data['base']
    if not isinstance(base, str) or base in seen:
        raise error('%s: base: %r is not another profile\'s name or file' % (where, base))
    below = merged_with_base(read(base), read, base, error, tuple(seen) + (base,))
    out = dict(below)
    out.update({k: v for k, v in data.items() if k != 'base'})
    return out
