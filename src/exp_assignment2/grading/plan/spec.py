"""A run's specification: everything a worker needs to know to run one
submission once, decided on the teacher's side before any run starts, and
sent as a plain dict (``to_dict``/``from_dict``; JSON-safe, so no class of the
grader is pickled to a worker). Also the one precedence of settings (no ROS).

Settings: the command line over ``grading.yaml`` over the profile, for every
key (:func:`settings`).
"""

FIELDS = ('name', 'path', 'kind', 'label', 'seed', 'profile', 'duration',
          'real_time_factor', 'hidden', 'version', 'package', 'commands', 'commands_from',
          'readme_commands', 'notes', 'refused', 'packages', 'build', 'debian', 'rejected',
          'release', 'release_why', 'releases_next', 'starts', 'build_packages', 'git',
          'episode', 'ball_script')


class RunSpec(object):
    """One run's specification. ``commands`` are exactly what the run
    starts (the profile's world first, ``{package}``/``{sim}`` put in); ``starts``: the same
    commands with when each starts and from which folder
    (:mod:`~exp_assignment2.grading.plan.starts`; empty: ``delay`` apart, as before there were
    plans); ``readme_commands``: every command the README gives, each ``{'command', 'ran', 'why',
    'kind'}``; ``build_packages``: the submission's packages its README's build lines name;
    ``refused``: why the run must not run (a mistake in the teacher's settings for it, or the
    grader's own failure to read it: ``grader_error``), or None; ``rejected``: why the submission
    cannot be taken at all (``not_built``: it does not unpack, it holds no package, it is not a
    folder or an archive), or None; ``packages``: every package found, each ``{'name', 'rel',
    'built', 'why'}``; ``build``: the folders (relative to the submission's root) of those the run
    builds, the main one first; ``debian``: what the build needs from Debian (installed before the
    run, outside its sandbox); ``release``: the ROS release the simulator plays (None: the
    teacher's environment's), ``release_why``, and ``releases_next``: those to run it in when its
    checks fail in this one
    (:mod:`~exp_assignment2.grading.plan.ros_release`); ``git``: the commit a git repository is
    graded at, and why (:func:`~exp_assignment2.grading.entry.git_entries.choose`), or None;
    ``episode``: which of the submission's episodes it is (``index``, the ball's ``seed``,
    ``visibility``) and ``ball_script``: the course the simulator plays for the ball in it
    (None: the student's ball node moves it; :mod:`~exp_assignment2.grading.plan.episodes`)."""

    def __init__(self, **fields):
        unknown = set(fields) - set(FIELDS)
        if unknown:
            raise TypeError('RunSpec: unknown fields %s' % ', '.join(sorted(unknown)))
        defaults = {'seed': 1, 'hidden': [], 'version': '', 'package': None, 'commands': [],
                    'commands_from': '', 'readme_commands': [], 'notes': [], 'refused': None,
                    'real_time_factor': 1.0, 'label': None, 'packages': [], 'build': [],
                    'debian': [], 'rejected': None, 'release': None, 'release_why': '',
                    'releases_next': [], 'starts': [], 'build_packages': [], 'git': None,
                    'episode': None, 'ball_script': None}
        for key in FIELDS:
            value = fields.get(key, defaults.get(key))
            setattr(self, key, list(value) if isinstance(value, (list, tuple)) else value)
        if self.label is None:
            self.label = self.name
        if self.duration is None and self.profile:
            self.duration = self.profile['duration']

    def to_dict(self):
        return {key: getattr(self, key) for key in FIELDS}

    @classmethod
    def from_dict(cls, data):
        return cls(**{key: data[key] for key in FIELDS if key in data})

    def __eq__(self, other):
        return isinstance(other, RunSpec) and self.to_dict() == other.to_dict()

    def __repr__(self):
        return 'RunSpec(%r, seed=%r)' % (self.label, self.seed)


# key, the command line's option, grading.yaml's key, the profile's key, the default
SETTINGS = (
    ('duration', 'duration', 'duration', 'duration', None),
    ('real_time_factor', 'real_time_factor', 'real_time_factor', None, 1.0),
    ('delay', None, 'delay', 'delay', 5),
)


def _pick(cli, option, teacher, teacher_key, profile, profile_key, default):
    if option and cli.get(option) is not None:
        return cli[option], 'the command line'
    if teacher_key and teacher.get(teacher_key) is not None:
        return teacher[teacher_key], 'grading.yaml'
    if profile_key and profile is not None and profile.get(profile_key) is not None:
        return profile[profile_key], 'the profile'
    return default, 'the default'


def settings(cli, teacher, load_profile):
    """({'profile': the profile (a dict), 'profile_source': its name or file,
    'duration', 'real_time_factor', 'delay'}, {key: where its value came from})
    from the command line's values
    ``cli`` (a dict; None: not given), the teacher's file ``teacher`` (a dict)
    and ``load_profile(name)``. For every key: the command line, else
    grading.yaml, else the profile (chosen first, by the same rule), else
    the default."""
    name, where = _pick(cli, 'profile', teacher, 'profile', None, None, 'dog')
    profile = dict(load_profile(name))
    chosen, whence = {}, {'profile': where}
    for key, option, teacher_key, profile_key, default in SETTINGS:
        chosen[key], whence[key] = _pick(cli, option, teacher, teacher_key, profile,
                                         profile_key, default)
    profile['delay'] = chosen['delay']        # the driver reads it from the profile
    chosen.update(profile=profile, profile_source=name, duration=float(chosen['duration']),
                  real_time_factor=float(chosen['real_time_factor']))
    return chosen, whence
