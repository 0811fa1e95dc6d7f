"""What the index says of how its runs were made (no ROS): a grading that
resumed an earlier one (the runs kept, those run again and why) and one
stopped before its end (the runs not run, and how to run them). The grading
writes ``resume.json`` (run.resume's summary); the index reads it."""
import json
import os
import time

from exp_assignment2.grading.report.html import e as _e
from exp_assignment2.grading.run.resume import NEW, runs

NAME = 'resume.json'


def write(report_dir, summary):
    """``summary`` (run.resume.Resume.summary) with its time, as resume.json."""
    with open(os.path.join(report_dir, NAME), 'w') as f:
        json.dump(dict(summary, at=time.time()), f, indent=1)


def read(report_dir):
    try:
        with open(os.path.join(report_dir, NAME)) as f:
            data = json.load(f)
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) else None


def paragraph(report_dir):
    """[HTML] for the index's top ([] for a grading that was neither resumed nor stopped)."""
    said = read(report_dir)
    if not said:
        return []
    parts = []
    when = time.strftime('%Y-%m-%d %H:%M', time.localtime(said.get('at') or 0))
    again = said.get('again') or []
    if said.get('resumed'):
        parts.append('<p class="resumed">The grading of %s resumed an earlier one: %s '
                     'kept (finished, of the same plan), %d run then.</p>' % (
                         _e(when), runs(len(said.get('kept') or [])), len(again)))
        told = [(label, why) for label, why in again if why != NEW]
        if told:
            parts.append('<details><summary>run again, and why</summary><ul>%s</ul></details>'
                         % ''.join('<li>%s: %s</li>' % (_e(label), _e(why))
                                   for label, why in told))
    stopped = said.get('stopped') or []
    if stopped:
        parts.append('<p class="stopped"><b>Stopped before its end</b> (%s): %s not run '
                     '(%s). <code>grade</code> again with the same <code>--out</code> runs '
                     'them and keeps the runs that finished.</p>' % (
                         _e(when), runs(len(stopped)), _e(', '.join(stopped[:20]) +
                                                   (', ...' if len(stopped) > 20 else ''))))
    return parts
