"""A run's monitor (no ROS): the driver started in the sandbox, watched until
the run is over, and what it measured put in the run's record. Why the run
ends is :func:`~exp_assignment2.grading.run.ending.end_reason`'s to say; the
monitor only keeps its facts up to date and does what it says.
"""
import json
import os
import subprocess
import threading
import time

from exp_assignment2.grading.judge import logs
from exp_assignment2.grading.paths import INSIDE
from exp_assignment2.grading.plan import starts
from exp_assignment2.grading.run import cpu
from exp_assignment2.grading.run import ending
from exp_assignment2.grading.run.files import directory_size, log_sizes

START_SLACK = 120.0          # wall s on top of the duration: set-up, starting, ending
WORK_LIMIT = 2 * 1024 ** 3   # bytes the work directory may hold
DISK_LOOK = 5.0              # wall s between two looks at the work directory's size


def _facts(run, rtf, t0):
    """The run's :class:`~exp_assignment2.grading.run.ending.RunFacts` at its start (a
    first attempt beside other runs may end starving: ``settings.may_end_starved``)."""
    duration = run.settings.duration
    span = starts.span(run.spec.starts) if run.spec.starts else \
        len(run.spec.commands) * run.settings.profile['delay']
    pace = rtf if run.settings.may_end_starved and rtf > 0 else None
    return ending.RunFacts(duration, duration / (rtf if rtf > 0 else 1.0) * 1.5 + START_SLACK,
                           t0, span, pace=pace)


def watch(run, box, truth, plan, rtf, result):
    """Start the driver in ``box`` and watch until the run is over; the
    run's measures in ``result``."""
    proc = box.start(['/usr/bin/python3', INSIDE, plan], stdout=subprocess.PIPE)
    events = run.events
    reader = threading.Thread(target=read_events, daemon=True, args=(
        proc, events, os.path.join(run.record, 'events.jsonl'), run.news))
    reader.start()
    t0 = time.monotonic()
    facts = _facts(run, rtf, t0)
    required = logs.RequiredWatch(run.work)
    asked = None            # when the driver was asked to end its commands
    run.state = 'building'
    last_size_check = 0.0
    pace = cpu.Pace()
    while True:
        run.news.wait(0.25)       # a driver event, or the limits' next look
        run.news.clear()
        now = time.monotonic()
        facts.driver_exited = proc.poll() is not None
        if facts.built_at is None:
            built = next((e for e in events if e.get('event') == 'built'), None)
            if built is not None:
                facts.built_at, facts.build_failed = now, built.get('rc') != 0
                run.state = 'running'
        if asked is not None:
            if facts.driver_exited or ending.stop_overdue(asked, now):
                break
            continue
        facts.cancelled = run.stop_event.is_set()
        facts.truth = truth.latest
        ending.note_pace(facts, now)
        if facts.truth is not None and pace.look(box.groups.pids(), facts.truth[0],
                                                    now) is not None:
            run.pace = pace.cost      # the teacher's side admits runs by it (tasks._watch)
        facts.all_exited = all_exited(events)
        if facts.built_at is not None and not facts.required_died:
            facts.required_died = required.death()
        if now - last_size_check > DISK_LOOK:
            last_size_check = now
            facts.over_disk = directory_size(run.work) > WORK_LIMIT
        reason = ending.end_reason(facts, now)
        if reason in ending.AT_ONCE:
            result['ended_by'] = reason
            break
        if reason:
            asked = now
            _ask_to_stop(proc, box, truth, run.work, reason, facts, result)
            run.state = 'ending'
    result.setdefault('log_sizes', log_sizes(run.work))
    result['all_gone'] = box.kill()
    result['peak_memory_mb'] = (box.groups.peak_memory() or 0) / 2 ** 20
    result['oom'] = box.groups.oom_killed()
    if result['all_gone']:
        box.groups.remove()
    reader.join(2.0)
    truth.close()
    result['truth'] = {'states': truth.states, 'frames': truth.frames,
                       'topics': truth.topics, 'dropped': truth.dropped,
                       'simulator': truth.simulator and truth.simulator[1],
                       'refused_peers': truth.refused,
                       'sim_time': truth.latest[0] if truth.latest else 0.0}
    result['real_time_factor'] = truth.real_time_factor()
    result['wall_time'] = time.monotonic() - t0
    result['sandbox_exit'] = proc.returncode
    result['events'] = events
    built = next((e for e in events if e.get('event') == 'built'), None)
    if built is not None:
        result['build'] = {'rc': built.get('rc'), 'error': built.get('error')}


def _ask_to_stop(proc, box, truth, work, reason, facts, result):
    """The end's reason and the run's state then in ``result``; the driver
    asked to end its commands."""
    result['ended_by'] = reason
    result['ended_at'] = truth.latest[0] if truth.latest else 0.0   # simulated s
    if reason == 'required_node_died':
        result['required_node'] = facts.required_died
    if reason == 'starved':
        result['starved_factor'] = round(ending.starving(facts), 3)
    result['cpu_s'], result['memory_mb'] = cpu.snapshot(box.groups.pids())
    result['log_sizes'] = log_sizes(work)
    try:
        proc.stdin.write('stop\n')
        proc.stdin.flush()
    except (OSError, ValueError):
        pass


def all_exited(events):
    """Every command the driver started has exited (and one was started)."""
    started = {e['index'] for e in events if e.get('event') == 'started'}
    exited = {e['index'] for e in events if e.get('event') == 'exited'}
    return bool(started) and started <= exited


def read_events(proc, events, path, news):
    """The driver's events (JSON lines on its stdout) into ``events`` and ``path``."""
    with open(path, 'w') as out:
        for line in proc.stdout:
            out.write(line)
            if len(events) > 10000:
                continue
            try:
                event = json.loads(line)
            except ValueError:
                event = {'event': 'output', 'text': line.rstrip()[:500]}
            if isinstance(event, dict):
                events.append(event)
                news.set()
