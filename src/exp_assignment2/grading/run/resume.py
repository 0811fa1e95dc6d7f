"""A grading started again with the same ``--out`` (no ROS): a run that
finished, of the same plan, is kept; the others run.

*Finished*: its record (``runs/LABEL/record/run.json``) is there, whole,
with a verdict of its own, and its directory is whole. The record is written
last, after the run's logs and frames and the teacher's part, and taken away
first when a new attempt starts over the directory (grading.record): a kill
at any moment leaves a whole record or none. A grader error is no verdict of
the student's: such a run is run again, as is one stopped half way.

*The same plan*: what the teacher's side planned the run from is kept in its
record's teacher's part (``planned``): the digest of its RunSpec (its
commands, profile, duration, release, seed, ...; not where this grading put
its files) and of the submission's files as graded (the teacher's side's copy
of them). Another profile, another duration, a file of the submission changed:
the run is run again, and the terminal says why.
"""
import hashlib
import json
import os
import shutil

from exp_assignment2.grading import record

# where this grading put things (the folder, the report, its scratch copies): not the run's plan
WHERE = ('hidden', 'path')
NEW, NOT_FINISHED = 'not run before', 'not finished'


def runs(count):
    """'1 run', '3 runs'."""
    return '%d run%s' % (count, '' if count == 1 else 's')


def spec_fields(spec, scratch=None):
    """The RunSpec's fields that make the run what it is, as JSON reads them
    back (the teacher's side's scratch copies, named in a note, as ``<copy>``)."""
    data = {k: v for k, v in spec.to_dict().items() if k not in WHERE}
    text = json.dumps(data, sort_keys=True, default=str)
    if scratch:
        text = text.replace(json.dumps(scratch)[1:-1], '<copy>')
    return json.loads(text)


def digest(data):
    return hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode()).hexdigest()


def files_digest(folder):
    """The digest of every file under ``folder``: its path, kind (a link's
    target, a file's bytes and whether it is executable)."""
    found = hashlib.sha256()
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        for name in sorted(dirs + files):
            path = os.path.join(root, name)
            rel = os.path.relpath(path, folder)
            if os.path.islink(path):
                found.update(('L %s -> %s\n' % (rel, os.readlink(path))).encode())
            elif os.path.isfile(path):
                with open(path, 'rb') as f:
                    content = hashlib.sha256(f.read()).hexdigest()
                found.update(('F %s %d %s\n' % (rel, os.access(path, os.X_OK), content)).encode())
            elif os.path.isdir(path):
                found.update(('D %s\n' % rel).encode())
    return found.hexdigest()


def content_digest(submission, copies):
    """The digest of a submission as graded: its teacher's side's copy (what
    was taken of it), or why it cannot be taken."""
    if submission.kind == 'other':
        return digest(['other', submission.why])
    copy = copies.of(submission)
    parts = [files_digest(copy.dest) if os.path.isdir(copy.dest) else '']
    if copy.error is not None:
        parts.append(str(copy.error))
    return digest(parts)


def _differs(then, now):
    """What of the plan differs, said in a few words."""
    said = []
    for key in sorted(set(then) | set(now)):
        if then.get(key) == now.get(key):
            continue
        a, b = then.get(key), now.get(key)
        if isinstance(a, dict) and isinstance(b, dict):
            keys = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
            said.append('%s (%s)' % (key, ', '.join(keys)))
        elif isinstance(a, (int, float, str, type(None))) and \
                isinstance(b, (int, float, str, type(None))) and len(str(a) + str(b)) < 60:
            said.append('%s: %s then, %s now' % (key, a, b))
        else:
            said.append(key)
    return '; '.join(said)


def whole(run_dir, run):
    """The run's directory holds what its record says it has: the driver's
    events, and the logs of a run that was built (unless its worker did not
    send them back: the teacher's part says what was cut)."""
    cut = ' '.join(record.teacher(run, 'cut'))
    if run.get('events') and 'record/events.jsonl' not in cut and \
            not os.path.isfile(os.path.join(run_dir, 'record', 'events.jsonl')):
        return False
    return not run.get('build') or 'work/logs/' in cut or \
        os.path.isdir(os.path.join(run_dir, 'work', 'logs'))


def why_again(run_dir, old, planned):
    """Why the run in ``run_dir`` (its record ``old``, or None) is run again,
    or None: it is kept."""
    if old is None:
        return NOT_FINISHED if os.path.isdir(run_dir) else NEW
    if not old.get('verdict') or old.get('ended_by') == 'cancelled':
        return NOT_FINISHED
    if old['verdict'] == 'grader_error':
        return 'a grader error (%s): graded again' % (old.get('reason') or '')[:120]
    then = (old.get('teacher') or {}).get('planned')
    if not then:
        return 'recorded by a grader that kept no plan of it'
    if then.get('spec') != planned['spec']:
        return 'planned otherwise: %s' % (
            _differs(then.get('spec_fields') or {}, planned['spec_fields']) or 'its spec')
    if then.get('content') != planned['content']:
        return "the submission's files changed since"
    if not whole(run_dir, old):
        return 'its directory is not whole'
    return None


class Resume(object):
    """What a grading keeps of the runs already in ``runs_dir``: ``keep(run)``
    for each run it plans (it sets ``run.planned``); ``kept``, and ``again``
    [(label, why)], said by :meth:`lines`."""

    def __init__(self, runs_dir, copies, log=print):
        self.runs_dir, self.copies, self.log = runs_dir, copies, log
        self.kept, self.again = [], []
        self._content = {}

    def planned(self, run):
        """What ``run`` is planned from (record.TEACHER_FIELDS ``planned``)."""
        key = os.path.abspath(run.submission.path)
        if key not in self._content:
            self._content[key] = content_digest(run.submission, self.copies)
        fields = spec_fields(run.spec, self.copies.scratch)
        return {'spec': digest(fields), 'content': self._content[key], 'spec_fields': fields}

    def keep(self, run):
        """The run's finished record when it is of this plan (kept: not run
        again), else None: its earlier record, if any, is taken away, so that
        no report shows it while it runs again."""
        run.planned = self.planned(run)
        old = record.load(run.record)
        why = why_again(run.dir, old, run.planned)
        if why is None:
            self.kept.append(run.label)
            return old
        if old is not None:
            record.unfinish(run.record)
        self.again.append((run.label, why))
        return None

    def resumed(self):
        """Something was there before: the grading resumes one."""
        return bool(self.kept) or any(why != NEW for _, why in self.again)

    def say(self):
        """The terminal told what is kept and what runs again (nothing when
        nothing was there before)."""
        for line in self.lines():
            self.log(line)

    def lines(self, shown=20):
        """The terminal's lines: how many kept and to run, and why each of
        those planned otherwise runs again."""
        if not self.resumed():
            return []
        counts = {}
        for _, why in self.again:
            kind = why if why in (NEW, NOT_FINISHED) else 'changed'
            counts[kind] = counts.get(kind, 0) + 1
        lines = ['resuming: %s kept, %d to run%s' % (
            runs(len(self.kept)), len(self.again), ' (%s)' % ', '.join(
                '%d %s' % (n, kind) for kind, n in sorted(counts.items())) if counts else '')]
        told = [(label, why) for label, why in self.again if why not in (NEW, NOT_FINISHED)]
        lines += ['  %s: run again: %s' % item for item in told[:shown]]
        if len(told) > shown:
            lines.append('  and %d more (the report lists them)' % (len(told) - shown))
        return lines

    def drop_others(self, runs):
        """After a whole grading: the runs of ``runs_dir`` of a submission
        graded now that are not among ``runs`` (an earlier plan's: another
        --repeat, a release no longer tried), taken away; [their labels]."""
        names, labels = {r.spec.name for r in runs}, {r.label for r in runs}
        dropped = []
        for old in record.load_all(self.runs_dir):
            if old['name'] in names and old['label'] not in labels:
                where = os.path.join(self.runs_dir, old['label'])
                record.unfinish(os.path.join(where, 'record'))
                shutil.rmtree(where, ignore_errors=True)
                dropped.append(old['label'])
        return dropped

    def summary(self, runs, stopped):
        """What the report says of it (report.resumed): the runs kept, those
        run again and why, those not run (``stopped``: the teacher stopped the
        grading)."""
        return {'kept': list(self.kept), 'again': [list(item) for item in self.again],
                'stopped': [r.label for r in stopped], 'resumed': self.resumed(),
                'runs': len(runs)}
