"""A recorded run (``record:=true``) as plain data, for ``plot_run.py BAG [-o PNG]``
(the command line: :mod:`exp_assignment2.nodes.plot_run`).

The scenario comes from the topics in the bag: ``/robot/odom`` is the dog
(scenario A), ``/odom`` with ``/state`` is MiRo (scenario B). The bag is read
with Debian's ``rosbag``, whose message classes are generated from the
definitions stored in the bag, so no catkin build is needed. This module
turns messages into plain data (a :class:`Run`) and the pure functions below
cut it into coloured pieces; :mod:`.run_figure` draws it.
"""
import bisect
import os

from exp_assignment2.behaviour.miro import STATE_PARAM

DOG, MIRO = 'dog', 'miro'
STATES = ('SLEEP', 'NORMAL', 'PLAY')
# MiRo publishes the original's /state wording; both scenarios are drawn with one set
STATE_LABEL = dict((text, label) for label, text in STATE_PARAM.items())
DISAPPEAR_Z = 20.0      # the original lifted the ball to z = 20 to make it disappear
DOG_TOPICS = ('/clock', '/robot/odom', '/ball/odom', '/robot/state')
MIRO_TOPICS = ('/clock', '/odom', '/state', '/arrival', '/gesture', '/voice')


class PlotError(Exception):
    """A bag that cannot be drawn; the message is the one line the user sees."""


class Track(object):
    """A body's recorded positions: parallel lists ``t``, ``x``, ``y``, ``z``."""

    def __init__(self):
        self.t, self.x, self.y, self.z = [], [], [], []

    def append(self, t, x, y, z=0.0):
        """Adds one sample."""
        self.t.append(t)
        self.x.append(x)
        self.y.append(y)
        self.z.append(z)

    def length(self):
        """The path's length in metres."""
        return sum(((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5 for x0, y0, x1, y1 in
                   zip(self.x, self.y, self.x[1:], self.y[1:]))


class Run(object):
    """A recorded run as plain data, in simulated time (s).

    ``changes`` are the state changes [(t, 'SLEEP' | 'NORMAL' | 'PLAY')];
    ``arrivals`` MiRo's [(t, target_x, target_y, x, y, n)]; ``gestures``
    [(t, person_x, person_y, point_x, point_y)]; ``words`` [(t, text)].
    """

    def __init__(self, name, scenario, start, end, changes, robot, ball=None,
                 arrivals=(), gestures=(), words=()):
        self.name, self.scenario, self.start, self.end = name, scenario, start, end
        self.changes, self.robot, self.ball = changes, robot, ball
        self.arrivals, self.gestures, self.words = list(arrivals), list(gestures), list(words)

    @property
    def duration(self):
        """Seconds of simulated time the bag covers."""
        return max(0.0, self.end - self.start)


def detect_scenario(topics):
    """``DOG`` or ``MIRO`` from the bag's topic names; PlotError when neither."""
    topics = set(topics)
    if '/robot/odom' in topics:
        return DOG
    if '/odom' in topics and '/state' in topics:
        return MIRO
    raise PlotError('the bag has neither /robot/odom (scenario A, sim_world.launch) '
                    'nor /odom and /state (scenario B, miro.launch)')


def state_label(text):
    """The state's short label: 'SLEEP STATE' -> 'SLEEP'; other text stays as it is."""
    text = text.strip()
    return STATE_LABEL.get(text, text)


def state_changes(stamped):
    """[(t, label)] without repeats: a latched state is delivered again when a
    node respawns or a recorder reconnects, and that is no change."""
    changes = []
    for t, label in sorted(stamped, key=lambda tl: tl[0]):
        if not changes or changes[-1][1] != label:
            changes.append((t, label))
    return changes


def state_segments(changes, end):
    """[(t0, t1, label)]: each state from its change to the next one (the last to ``end``)."""
    ends = [t for t, _ in changes[1:]] + [max(end, changes[-1][0]) if changes else end]
    return [(t0, t1, label) for (t0, label), t1 in zip(changes, ends)]


def time_in_states(segments):
    """{label: seconds} summed over the segments."""
    totals = {}
    for t0, t1, label in segments:
        totals[label] = totals.get(label, 0.0) + (t1 - t0)
    return totals


def labels_at(times, changes):
    """The state at each time (None before the first change)."""
    starts = [t for t, _ in changes]
    out = []
    for t in times:
        i = bisect.bisect_right(starts, t) - 1
        out.append(changes[i][1] if i >= 0 else None)
    return out


def runs(xs, ys, keys):
    """Cuts a polyline into maximal pieces of equal key: [(key, xs, ys)].

    Each piece but the last also takes the first point of the next one, so
    the drawn pieces join up with no gap where the key changes.
    """
    pieces = []
    for i, key in enumerate(keys):
        if pieces and pieces[-1][0] == key:
            pieces[-1][1].append(xs[i])
            pieces[-1][2].append(ys[i])
            continue
        if pieces:
            pieces[-1][1].append(xs[i])
            pieces[-1][2].append(ys[i])
        pieces.append((key, [xs[i]], [ys[i]]))
    return pieces


def is_hidden(z):
    """True for a ball out of view: under the ground or lifted to the 'disappear' height."""
    return z < 0.0 or z >= DISAPPEAR_Z


def hidden_stretches(track):
    """[(t0, t1)] of the ball's hidden time (its x, y still move meanwhile)."""
    spans, since = [], None
    for t, z in zip(track.t, track.z):
        if is_hidden(z) and since is None:
            since = t
        elif not is_hidden(z) and since is not None:
            spans.append((since, t))
            since = None
    if since is not None:
        spans.append((since, track.t[-1]))
    return spans


def summary(run):
    """A few lines about the run: time span, time in each state, changes."""
    totals = time_in_states(state_segments(run.changes, run.end))
    title = {DOG: 'scenario A (dog and ball)', MIRO: 'scenario B (MiRo)'}[run.scenario]
    lines = ['%s: %s' % (run.name, title),
             '  simulated time %.1f .. %.1f s (%.1f s)' % (run.start, run.end, run.duration)]
    total = sum(totals.values()) or 1.0
    for label in list(STATES) + sorted(set(totals) - set(STATES)):
        seconds = totals.get(label, 0.0)
        lines.append('  %-7s %6.1f s %4.0f%%' % (label, seconds, 100.0 * seconds / total))
    lines.append('  %d state changes; robot path %.1f m'
                 % (max(0, len(run.changes) - 1), run.robot.length()))
    if run.ball is not None:
        spans = hidden_stretches(run.ball)
        lines.append('  ball hidden: %d stretches, %.1f s'
                     % (len(spans), sum(b - a for a, b in spans)))
    if run.scenario == MIRO:
        lines.append('  %d arrivals, %d gestures, %d words said on /voice'
                     % (len(run.arrivals), len(run.gestures), len(run.words)))
    return '\n'.join(lines)


def _sim_time(clock):
    """Bag time -> simulated time: rosbag stamps headerless messages with the
    recorder's time, which is /clock only when it ran with use_sim_time."""
    import numpy
    bag_t, sim_t = numpy.array([c[0] for c in clock]), numpy.array([c[1] for c in clock])
    if not clock or numpy.median(numpy.abs(bag_t - sim_t)) < 1.0:
        return lambda t: t      # the recorder ran on /clock: the bag's time is simulated time
    return lambda t: float(numpy.interp(t, bag_t, sim_t))


def _stamp(msg, fallback):
    stamp = msg.header.stamp.to_sec()
    return stamp if stamp > 0.0 else fallback


def read_bag(path):
    """(scenario, [(topic, message, bag time in s)]) of the topics drawn;
    PlotError when the file is missing, unreadable or of neither scenario."""
    if not os.path.isfile(path):
        raise PlotError('no such bag file: %s' % path)
    import rosbag     # Debian's python3-rosbag; imported here so the pure parts need no ROS
    try:
        bag = rosbag.Bag(path)
    except rosbag.ROSBagUnindexedException:
        raise PlotError('%s is not indexed (was the recording killed?); try rosbag reindex' % path)
    except (rosbag.ROSBagException, IOError, OSError, ValueError) as e:
        raise PlotError('%s is not a readable bag: %s' % (path, e))
    with bag:
        scenario = detect_scenario(bag.get_type_and_topic_info().topics)
        try:
            topics = DOG_TOPICS if scenario == DOG else MIRO_TOPICS
            return scenario, [(topic, m, t.to_sec()) for topic, m, t in
                              bag.read_messages(topics=topics)]
        except (rosbag.ROSBagException, IOError, OSError, ValueError) as e:
            raise PlotError('%s cannot be read to the end: %s' % (path, e))


def run_from_messages(name, scenario, messages):
    """A :class:`Run` from [(topic, message, bag time)]. Odometry and gestures
    keep their header stamps; the rest gets the bag time, turned into simulated
    time through /clock (the recorder stamps with its own clock, which is
    /clock only when it ran with use_sim_time)."""
    clock = [(t, m.clock.to_sec()) for topic, m, t in messages if topic == '/clock']
    sim = _sim_time(clock)
    robot_topic, state_topic = (('/robot/odom', '/robot/state') if scenario == DOG
                                else ('/odom', '/state'))
    robot, ball = Track(), (Track() if scenario == DOG else None)
    stamped, arrivals, gestures, words, times = [], [], [], [], [c[1] for c in clock]
    for topic, m, t in messages:
        when = sim(t)
        if topic in (robot_topic, '/ball/odom'):
            p = m.pose.pose.position
            (robot if topic == robot_topic else ball).append(_stamp(m, when), p.x, p.y, p.z)
        elif topic == state_topic:
            stamped.append((when, state_label(m.data)))
        elif topic == '/arrival' and len(m.data) >= 5:
            arrivals.append((when,) + tuple(m.data[:5]))
        elif topic == '/gesture':
            gestures.append((_stamp(m, when), m.person_x, m.person_y, m.point_x, m.point_y))
        elif topic == '/voice':
            words.append((when, m.data))
        times.append(when)
    times += robot.t + (ball.t if ball else [])
    if not times:
        raise PlotError('%s has no messages to draw' % name)
    return Run(name, scenario, min(times), max(times), state_changes(stamped),
               robot, ball, arrivals, gestures, words)


def read_run(path):
    """Reads a bag into a :class:`Run`; PlotError when it cannot be drawn."""
    scenario, messages = read_bag(path)
    return run_from_messages(os.path.basename(path), scenario, messages)
