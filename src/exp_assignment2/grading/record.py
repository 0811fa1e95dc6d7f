"""A run's record (``RUN/record/run.json``): its fields declared, one writer,
one reader (no ROS).

Like the CARLA leaderboard's route record: the runner, the cluster (a run
its workers lost, a run refused) and the report all handle one shape,
:class:`RunRecord`, whose fields are :data:`FIELDS` (a field not there is
refused), written only by :func:`write` and read only by
:func:`load`/:func:`load_all`. Those of a run that did not run are left out.

The run's fields are the worker's (or, for a run that never reached one,
the teacher's side's, made once). What the teacher's side adds once a
worker's run came back is its own part, :data:`TEACHER_FIELDS`, kept in
``teacher.json`` beside ``run.json`` and read as the record's ``teacher``:
the worker's fields are never written again.

A run is *finished* when its ``run.json`` is there (:func:`load` reads it,
with a verdict): :func:`write` puts it last, after ``teacher.json``, and a
run's directory holds its logs and frames before it is written; a new
attempt over a run's directory first takes it away (:func:`unfinish`). So a
kill at any moment leaves a whole record or none, and ``grade`` started again
keeps only whole ones (:mod:`~exp_assignment2.grading.run.resume`).
"""
import json
import os

NAME, TEACHER_NAME = 'run.json', 'teacher.json'

FIELDS = (
    # who
    ('name', "the submission's name (its entry of the folder)"),
    ('label', "the run's: the name, -rN for a repeat, -RELEASE when run again in another "
              'ROS release'),
    ('seed', "the run's seed"),
    ('version', 'the package version of the grader that ran it'),
    ('profile', "the profile's name"),
    ('run_id', "this attempt's id (a uuid): a run kept by a resumed grading keeps it"),
    # what was asked (plan.spec.RunSpec's, as planned)
    ('commands', 'what the run starts, exactly'),
    ('commands_from', 'where they came from: grading.yaml, the README, the profile'),
    ('readme_commands', "every command of the README: ran, or left out and why"),
    ('notes', "what the planning and the run noted (files left out, a real-time factor of 1)"),
    ('packages', 'every package of the submission: name, rel, built, why'),
    ('package', "the main package's name, as built"),
    ('release', 'the ROS release the simulator played'),
    ('release_why', 'why that release'),
    ('duration', "the run's own simulated s"),
    ('real_time_factor_asked', 'the factor it was run at (1 when the code waits on the '
                               'wall clock)'),
    ('repeat_command', 'the command line that runs it again by hand'),
    ('limits', "the sandbox's memory and process limits, as set"),
    ('git', "a git repository's commit graded, how it was chosen, the commits after it, days "
            'late and points off (entry.git_entries.choose)'),
    ('episode', "which of the submission's episodes it is: index, the scripted ball's seed, "
                'visibility (plan.episodes), or None'),
    # how it went
    ('started', 'when the run started (epoch s)'),
    ('finished', 'when its record was written (epoch s)'),
    ('events', "the driver's events"),
    ('build', "the build's outcome as the driver sent it: rc, and error (file, line, message)"),
    ('ended_by', 'why the run ended: run.ending.REASONS, or not_run (it never started)'),
    ('ended_at', 'the simulated s then'),
    ('required_node', "roslaunch's name of the required node whose death ended it"),
    ('starved_factor', 'the real-time factor it kept over the last 30 wall s when it was '
                       'ended for falling behind beside other runs (ended_by starved)'),
    ('log_sizes', '{log: bytes} at the end'),
    ('truth', 'the ground truth: states, frames, topics, dropped, simulator, refused_peers, '
              'sim_time'),
    ('real_time_factor', 'simulated s per wall s, as run'),
    ('wall_time', 'wall s from the start of the driver to the end'),
    ('cpu_s', "the run's processes' CPU s when it was asked to end"),
    ('memory_mb', 'and their memory then'),
    ('peak_memory_mb', "the sandbox's peak memory"),
    ('oom', 'the memory limit killed a process'),
    ('all_gone', "every process of the sandbox was gone once killed"),
    ('sandbox_exit', "the driver's exit code"),
    # an end before or outside the run (judge.seen's facts of it)
    ('refused', 'why it was not run: grading.yaml is wrong about it, or the grader could not '
                'read it'),
    ('rejected', 'why the submission cannot be taken: it does not unpack, holds no package, '
                 'is not a folder or an archive'),
    ('lost', "the error with which Dask gave up on it (its workers kept dying)"),
    ('grader_fault', "a fault of the grader's with it: {'what': what failed, 'error': the "
                     "exception and where}"),
    ('sandbox_error', 'why its sandbox could not be made'),
    # the verdict (judge.verdicts)
    ('verdict', 'one of judge.verdicts.VERDICTS'),
    ('reason', 'why, in a line'),
    ('checks', "the profile's checks (of a crashed or timed-out run too: judged until its end; "
               'a check not run has judged False and passed None)'),
    ('checks_until', 'the verdict of a run whose checks were judged until it ended early'),
    ('errors', 'the Python errors of its logs (the first 20)'),
    ('error_count', 'how many'),
    ('died', 'the nodes that died, each with why'),
    ('launch_errors', 'the nodes roslaunch could not start'),
    ('keyboard', 'where a node waited for keyboard input nobody typed'),
    ('roles', 'the robot, head, camera and ball judged, each with why (judge.roles)'),
    ('release_evidence', "what a failed run shows of its ROS release (judge.steering): "
                         'whether another release may be the cause, and why'),
    # the teacher's side's part
    ('teacher', 'what the teacher\'s side added once the run came back: TEACHER_FIELDS'),
)
TEACHER_FIELDS = (
    ('workers', 'the workers that ran it, in order (more than one: run again)'),
    ('notes', "the teacher's side's notes (a run done again after its worker was lost)"),
    ('cut', 'what its worker did not send back whole'),
    ('release_next', "the next ROS release the course allows: {'release', 'tried', 'why'} "
                     '(run.dispatch.in_next_release)'),
    ('planned', "what the teacher's side planned it from: {'spec': the digest of its RunSpec, "
                "'content': of its submission's files, 'spec_fields': the RunSpec's fields} "
                '(run.resume: a grading started again keeps it only when they are the same)'),
)
# what an older grader wrote among the run's own fields
_FORMERLY_OWN = ('workers', 'cut')
_KNOWN = {key for key, _ in FIELDS}
_KNOWN_TEACHER = {key for key, _ in TEACHER_FIELDS}


def _check(key, value):
    if key not in _KNOWN:
        raise TypeError('RunRecord: unknown field %r (record.FIELDS)' % (key,))
    if key == 'teacher':
        unknown = set(value) - _KNOWN_TEACHER
        if unknown:
            raise TypeError('RunRecord: unknown teacher field %s (record.TEACHER_FIELDS)'
                            % ', '.join(sorted(unknown)))



class RunRecord(dict):
    """One run's record: a dict of :data:`FIELDS` (it travels as one), which
    refuses any other key."""

    def __init__(self, *args, **fields):
        super(RunRecord, self).__init__(*args, **fields)
        for key, value in self.items():
            _check(key, value)

    def __setitem__(self, key, value):
        _check(key, value)
        super(RunRecord, self).__setitem__(key, value)

    def update(self, *args, **fields):
        for key, value in dict(*args, **fields).items():
            self[key] = value

    def setdefault(self, key, default=None):
        if key not in self:
            self[key] = default
        return self[key]

    @classmethod
    def new(cls, name, label, seed, **fields):
        return cls(name=name, label=label, seed=seed, **fields)

    def to_json(self):
        return json.dumps(self, indent=1, default=str)


def _put(path, text):
    with open(path + '.tmp', 'w') as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())            # on disk before its name says it is there
    os.replace(path + '.tmp', path)      # a reader never sees half of one


def write(record_dir, record=None, teacher=None):
    """The one writer: ``record`` (a RunRecord, or a dict of its fields, or
    the bytes of a worker's run.json, kept byte for byte) as
    ``record_dir/run.json``, and the teacher's part (``teacher``, a dict of
    TEACHER_FIELDS, or the record's own ``teacher``) as ``teacher.json``
    beside it, added without writing the run's fields again; run.json last
    (its presence says the run is finished); the record as it now is."""
    os.makedirs(record_dir, exist_ok=True)
    text = None
    if isinstance(record, bytes):       # as its worker wrote it: checked, never rewritten
        try:
            data = json.loads(record.decode('utf-8'))
            RunRecord(data)
        except (ValueError, TypeError) as exc:
            raise ValueError('record.write: not a run record: %s' % exc)
        if 'teacher' in data:
            raise ValueError('record.write: a worker\'s record holds no teacher\'s part')
        text = record.decode('utf-8')
    elif record is not None:
        record = RunRecord(record)
        own = record.pop('teacher', None)
        if own is not None and teacher is not None:
            raise TypeError('record.write: the teacher\'s part given twice')
        teacher = own if own is not None else teacher
        text = record.to_json()
    if teacher is not None:
        _check('teacher', teacher)
        _put(os.path.join(record_dir, TEACHER_NAME), json.dumps(teacher, indent=1, default=str))
    if text is not None:
        _put(os.path.join(record_dir, NAME), text)
    return load(record_dir)


def unfinish(record_dir):
    """A new attempt starts over the run's directory: its record goes first
    (run.json, then the teacher's part), so that no record is left beside
    the logs and frames of another attempt."""
    for name in (NAME, TEACHER_NAME):
        try:
            os.unlink(os.path.join(record_dir, name))
        except FileNotFoundError:
            pass


def _read(path):
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) else None


def load(record_dir):
    """The RunRecord in ``record_dir`` (its teacher's part as ``teacher``), or
    None if it has none (or not JSON, or with a field it does not know)."""
    data = _read(os.path.join(record_dir, NAME))
    if data is None:
        return None
    teacher = _read(os.path.join(record_dir, TEACHER_NAME))
    formerly = {key: data.pop(key) for key in _FORMERLY_OWN if key in data}
    if teacher is not None or formerly:
        data['teacher'] = dict(formerly, **(teacher or {}))
    try:
        return RunRecord(data)
    except TypeError:
        return None


def load_all(runs_dir):
    """[RunRecord] of every run directory of ``runs_dir`` that has one, by label."""
    if not os.path.isdir(runs_dir):
        return []
    found = (load(os.path.join(runs_dir, label, 'record'))
             for label in sorted(os.listdir(runs_dir)))
    return [r for r in found if r is not None]


def teacher(run, key):
    """The teacher's side's ``key`` (TEACHER_FIELDS) of a run's record ([] if none)."""
    return list((run.get('teacher') or {}).get(key) or [])


def notes(run):
    """Every note of a run: the planning's and the run's, then the teacher's side's."""
    return list(run.get('notes') or []) + teacher(run, 'notes')


def traceback_line(exc):
    """``TypeError: ... (planning.py:42)``: the exception and where it was raised."""
    import traceback
    frames = traceback.extract_tb(exc.__traceback__)
    where = ' (%s:%d)' % (os.path.basename(frames[-1].filename), frames[-1].lineno) \
        if frames else ''
    return '%s: %s%s' % (type(exc).__name__, str(exc)[:300], where)


def fault(what, exc):
    """A record's ``grader_fault``: the grader ``what`` (``failed while running
    it``), with ``exc``, the exception, and where it was raised."""
    return {'what': what, 'error': traceback_line(exc)}
