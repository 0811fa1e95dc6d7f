"""What the simulator's cost in a grading's runs went with (issue 61): for each
run, the simulator's cores at real time (its CPU s per simulated s) beside what
the student's world and nodes made it do, read from the simulator's own log in
the run's folder: the camera frames it drew a simulated s, counted in frames of
the course camera's 800 x 800 pixels (llvmpipe pays for pixels; a still scene is
not drawn again; a camera nobody watches is not drawn at all), the most nodes that
took ``/clock`` at once (every one gets every tick) and the models in the world.
Then the least-squares line through the runs, which says by how much each moves it.
Used by bench/grade.py and bench/real_class.py."""
import glob
import os
import re

MODELS = re.compile(r'simulator: (\d+) models')
FRAMES = re.compile(r'camera \S+: (\d+) frames, (\d+) of them of a still scene'
                    r'(?: \(not drawn again\), (\d+) x (\d+))?')
COURSE_PIXELS = 800 * 800       # the course camera's: a log without the size is of it
CLOCK = re.compile(r'topic\[/clock\] (adding|removing) connection')


def simulator_log(out, run):
    """The simulator's log of ``run`` in the grading folder ``out``, or None."""
    command = (run.get('truth') or {}).get('simulator') or ''
    found = re.search(r'__log:=\S*?/runs/%s/(\S+)' % re.escape(run.get('label') or ''),
                      command)
    if found:
        path = os.path.join(out, 'runs', run['label'], found.group(1))
        if os.path.isfile(path):
            return path
    paths = sorted(glob.glob(os.path.join(out, 'runs', run.get('label') or '-', 'work',
                                          'ros_home', 'log', '*', 'gazebo-*.log')))
    return next((p for p in paths if 'gazebo_gui' not in p), None)


def world_facts(path):
    """{'models', 'drawn' (in 800 x 800 frames), 'still', 'clock'} from a simulator's log
    (one written before it gave the camera's size: the course camera's)."""
    facts = {'models': 0, 'drawn': 0, 'still': 0, 'clock': 0}
    now = 0
    with open(path, errors='replace') as f:
        for line in f:
            found = MODELS.search(line)
            if found:
                facts['models'] = max(facts['models'], int(found.group(1)))
            found = FRAMES.search(line)
            if found:
                drawn = int(found.group(1)) - int(found.group(2))
                pixels = int(found.group(3)) * int(found.group(4)) if found.group(3) else \
                    COURSE_PIXELS
                facts['drawn'] += drawn * pixels / COURSE_PIXELS
                facts['still'] += int(found.group(2))
            found = CLOCK.search(line)
            if found:
                now += 1 if found.group(1) == 'adding' else -1
                facts['clock'] = max(facts['clock'], now)
    return facts


def rows(out, runs):
    """[(label, simulator cores, drawn frames a simulated s, /clock takers, models)]."""
    found = []
    for run in runs:
        cpu, sim = run.get('cpu_s') or {}, (run.get('truth') or {}).get('sim_time') or 0.0
        path = simulator_log(out, run)
        if not cpu.get('simulator') or sim < 10 or path is None:
            continue
        facts = world_facts(path)
        found.append((run['label'], cpu['simulator'] / sim, facts['drawn'] / sim,
                      facts['clock'], facts['models']))
    return found


def fit(found):
    """(a, b, c): simulator cores ~ a + b * drawn frames a s + c * /clock takers, or None."""
    if len(found) < 4:
        return None
    import numpy as np
    x = np.array([[1.0, r[2], r[3]] for r in found])
    y = np.array([r[1] for r in found])
    if np.linalg.matrix_rank(x) < 3:
        return None
    return tuple(float(v) for v in np.linalg.lstsq(x, y, rcond=None)[0])


def print_by_world(out, runs):
    found = rows(out, runs)
    if not found:
        print('the simulator\'s cost by world: no simulator log in %s' % out)
        return
    print('the simulator\'s cost by what the world made it do (cores at real time; camera '
          'frames drawn a simulated s, in 800 x 800 frames; the most nodes taking /clock at '
          'once; models):')
    for label, cores, drawn, clock, models in sorted(found, key=lambda r: r[1]):
        print('  %-24s %5.2f  %5.1f frames/s  %3d on /clock  %3d models' % (
            label, cores, drawn, clock, models))
    line = fit(found)
    if line:
        print('  least squares over %d runs: %.3f + %.4f a drawn frame a s + %.4f a node '
              'on /clock (30 frames/s: %.2f of a core)' % (
                  len(found), line[0], line[1], line[2], 30 * line[1]))
