"""A grading run as a task that can go to any machine (no ROS here, no Dask
either: :mod:`exp_assignment2.grading.run.cluster` hands these to Dask).

The submission travels as an archive (``pack_submission``, of the teacher's
side's copy of it: entry.copies); the worker runs it in a scratch directory
of its own (``run_task``) and sends back the run's
directory as an archive (``pack_run``): its record, its logs, its build
log and its windows' pictures, bounded in size (what was cut is said beside
it, for the record's teacher's part). The teacher's side unpacks it where
the report expects it (``unpack_run``). No filesystem is shared.
"""
import io
import os
import shutil
import tarfile
import threading
import time

from exp_assignment2.grading import record
from exp_assignment2.grading import scratch as grader_scratch
from exp_assignment2.grading.paths import PACKAGE_XML
from exp_assignment2.grading.run.runner import Run, RunSettings
from exp_assignment2.grading.plan.spec import RunSpec
from exp_assignment2.grading.entry.submissions import Submission

RETURN_LIMIT = 64 * 1024 * 1024        # bytes of a run's directory sent back
FILE_LIMIT = 8 * 1024 * 1024           # bytes of one log sent back (its start and end)
RECORD = os.path.join('record', record.NAME)      # sent whole, first
KEPT = ('record', 'work/logs', 'work/ros_home/log', 'work/overlay', 'work/display')
VERSION_ENV = 'EXP2_GRADER_VERSION'    # the version a worker announces (default: package.xml's)


class VersionMismatch(Exception):
    """A worker whose package is not the teacher's refuses the run."""


def package_version():
    import re
    path = PACKAGE_XML
    if os.environ.get(VERSION_ENV):
        return os.environ[VERSION_ENV]
    try:
        with open(path) as f:
            return re.search(r'<version>([^<]+)</version>', f.read()).group(1)
    except (OSError, AttributeError):
        return 'unknown'


def pack_submission(submission, copies):
    """(kind, bytes): an archive as it is; a directory as a .tar.gz of the
    teacher's side's copy of it (``copies``, entry.copies.Copies: links inside
    it kept, none out of it: no file of the teacher's machine travels with a
    submission; SubmissionError when it cannot be taken); a git repository as
    a .tar.gz of its copy, its chosen commit's tree."""
    if submission.kind not in ('dir', 'git'):
        with open(submission.path, 'rb') as f:
            return submission.kind, f.read()
    copy = copies.of(submission)
    copy.taken()
    buffer = io.BytesIO()
    with tarfile.open(fileobj=buffer, mode='w:gz') as archive:
        archive.add(copy.dest, arcname=os.path.basename(submission.path.rstrip('/')) or 'package')
    return 'tar', buffer.getvalue()


def _add(archive, rel, data):
    info = tarfile.TarInfo(rel)
    info.size = len(data)
    archive.addfile(info, io.BytesIO(data))
    return len(data)


def pack_run(run_dir, limit=RETURN_LIMIT):
    """(bytes, [what was cut]) of a run's directory: record and logs; its
    record (run.json) always whole, as the worker wrote it."""
    buffer, cut, total = io.BytesIO(), [], 0
    own = os.path.join(run_dir, RECORD)
    with tarfile.open(fileobj=buffer, mode='w:gz') as archive:
        if os.path.isfile(own) and not os.path.islink(own):
            with open(own, 'rb') as f:
                total += _add(archive, RECORD, f.read())
        for part in KEPT:
            base = os.path.join(run_dir, part)
            for root, dirs, files in os.walk(base):
                dirs[:] = [d for d in dirs if not (part == 'work/overlay' and d in
                                                  ('devel', 'src', 'stand_ins'))]
                for name in sorted(files):
                    if part == 'work/overlay' and name != 'build.log':
                        continue
                    path = os.path.join(root, name)
                    rel = os.path.relpath(path, run_dir)
                    if os.path.islink(path) or not os.path.isfile(path) or rel == RECORD:
                        continue
                    size = os.path.getsize(path)
                    if total + min(size, FILE_LIMIT) > limit:
                        cut.append('%s (%d bytes): over the %d MB a run sends back'
                                   % (rel, size, limit // 2 ** 20))
                        continue
                    if size > FILE_LIMIT:
                        with open(path, 'rb') as f:
                            head = f.read(FILE_LIMIT // 2)
                            f.seek(size - FILE_LIMIT // 2)
                            data = head + b'\n[... cut by the grader ...]\n' + f.read()
                        cut.append('%s: %d bytes, its middle cut' % (rel, size))
                    else:
                        with open(path, 'rb') as f:
                            data = f.read()
                    total += _add(archive, rel, data)
    return buffer.getvalue(), cut


def unpack_run(data, run_dir):
    """The run's directory from ``pack_run``'s bytes (regular files only,
    inside it), all but its record; the record's bytes (None: none came), for
    the teacher's side to write last (record.write), once the rest is there.
    An earlier record of the run is taken away first (record.unfinish)."""
    record.unfinish(os.path.join(run_dir, 'record'))
    shutil.rmtree(run_dir, ignore_errors=True)
    os.makedirs(run_dir)
    root = os.path.realpath(run_dir)
    own = None
    with tarfile.open(fileobj=io.BytesIO(data), mode='r:gz') as archive:
        for member in archive:
            target = os.path.realpath(os.path.join(run_dir, member.name))
            if not member.isfile() or not target.startswith(root + os.sep):
                continue
            if member.name == RECORD:
                with archive.extractfile(member) as src:
                    own = src.read()
                continue
            os.makedirs(os.path.dirname(target), exist_ok=True)
            with archive.extractfile(member) as src, open(target, 'wb') as out:
                shutil.copyfileobj(src, out)
    return own


def _watch(run, stop, report=None):
    """Until the run is over, ask ``stop`` whether the teacher cancelled it,
    and tell ``report`` each new pace of the run (``{'pace': CPU s per
    simulated s}`` as it runs, cpu.Pace) and, once, that it is ending
    (``{'ending': True}``: its commands asked to end, it costs little from
    then on). A ``stop`` or ``report`` that fails (the grading's connection
    closing as it ends) is no cancellation: the run goes on, and nothing is
    printed."""
    told = {}
    while not run.stop_event.is_set() and run.state != 'done':
        try:
            if report is not None:
                _tell(run, told, report)
            cancelled = stop()
        except Exception:       # noqa: BLE001 (Dask's comm errors have no common base)
            if run.state == 'done':
                return
            time.sleep(1.0)
            continue
        if cancelled:
            run.stop_event.set()
            return


def _tell(run, told, report):
    """What ``report`` was not yet told of ``run`` (``told``: what it was)."""
    if run.pace is not None and run.pace != told.get('pace'):
        told['pace'] = run.pace
        report({'pace': run.pace})
    if run.state == 'ending' and not told.get('ending'):
        told['ending'] = True
        report({'ending': True})


def run_task(payload, stop=None, scratch_root=None, report=None):
    """Run one payload (see cluster.payload) here; returns {'archive': the run's
    directory (pack_run), 'cut': what of it was not sent whole}.

    ``stop``: a function that waits a moment (a second) and says whether the
    teacher cancelled the grading; called until the run is over. ``report``:
    told each new pace of the run and its ending (_watch)."""
    mine = package_version()
    if payload['version'] != mine:
        raise VersionMismatch('this worker has exp_assignment2 %s, the teacher %s: it '
                              'refuses the run' % (mine, payload['version']))
    scratch = grader_scratch.make('grade', scratch_root)
    try:
        spec = RunSpec.from_dict(payload['spec'])
        kind = payload['packed_kind']
        source = os.path.join(scratch, 'submission' + {'zip': '.zip', 'tar': '.tar.gz'}[kind])
        with open(source, 'wb') as f:
            f.write(payload['data'])
        submission = Submission(spec.name, source, kind)
        submission.display_path = spec.path
        settings = RunSettings(spec.profile, os.path.join(scratch, 'runs'),
                               hidden=spec.hidden + [scratch],
                               real_time_factor=spec.real_time_factor,
                               duration=spec.duration, version=mine,
                               may_end_starved=(payload.get('attempt') or 1) == 1)
        run = Run(settings, spec, submission=submission)
        watcher = None
        if stop is not None:
            watcher = threading.Thread(target=_watch, args=(run, stop, report),
                                       daemon=True)
            watcher.start()
        try:
            run.go()
        finally:
            if watcher is not None:     # its last look ends within stop()'s second
                run.state = 'done'
                watcher.join(5.0)
        data, cut = pack_run(run.dir)
        return {'archive': data, 'cut': cut}
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
