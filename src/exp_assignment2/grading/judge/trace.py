"""The ground truth of one run as the checks read it (no ROS): :class:`Trace`,
and what a check raises when it cannot be decided (:class:`NotJudged`: a role
it needs cannot be told, or the run gave no occasion for the behaviour it
judges; :class:`Absent`: what it needs is not in the world)."""
import math

from exp_assignment2.grading.run.truth import read_record

RESET_JUMP = 3.0     # m in one sample (0.1 s): a reset or a teleport, not a path
DRIVEN_STEP = 0.05   # m: smaller steps of a smoothed path are jitter, not driving


class NotJudged(Exception):
    """The check cannot be run: a role it needs cannot be told (the reason)."""


class Absent(Exception):
    """What the check needs is not in the world (the reason): the check fails."""


def need(role):
    """A role's name, or :class:`Absent` / :class:`NotJudged` saying why there is none."""
    if role.name is None:
        raise (Absent if role.absent else NotJudged)(role.why)
    return role.name


class Trace(object):
    """The ground truth of one run: ``states`` (time-ordered dicts with ``t``,
    ``models``, ``joints`` and the counters ``fed``, ``placed`` and ``ignored``),
    ``topics`` (list of (t, topic, msg)), ``errors`` (the Python tracebacks found in
    the logs), ``models`` (what the simulator said of each model: name -> facts)
    and ``hello`` (the simulator's first record: its release, its ball script)."""

    def __init__(self, states=(), topics=(), errors=(), models=None, hello=None):
        self.states = sorted(states, key=lambda s: s['t'])
        self.topics = list(topics)
        self.errors = list(errors)
        self.models = dict(models or {})
        self.hello = hello or {}

    @classmethod
    def from_record(cls, record_dir, errors=()):
        """The run's trace, from its record
        (:func:`~exp_assignment2.grading.run.truth.read_record`)."""
        found = read_record(record_dir)
        return cls(found.states, found.topics, errors, found.models, found.hello)

    @property
    def duration(self):
        return self.states[-1]['t'] if self.states else 0.0

    def seen(self, model):
        """The model was in the world at some time of the record."""
        return model in self.models or any(model in s['models'] for s in self.states)

    def counter(self, kind, model):
        """The last count of ``fed`` (commands its drive took), ``placed`` or
        ``ignored`` (commands to a ball the course's script holds)."""
        return max([int((s.get(kind) or {}).get(model) or 0) for s in self.states] or [0])

    def travelled(self, model):
        """m the model went in the plane (resets and teleports left out)."""
        points = self.xy(model)
        return sum(step for step in (math.hypot(x1 - x0, y1 - y0) for (_, x0, y0), (_, x1, y1)
                                     in zip(points, points[1:])) if step < RESET_JUMP)

    def driven(self, model, step=DRIVEN_STEP):
        """m the model drove in the plane: its positions averaged over a second,
        counted in steps of at least ``step`` m (a still robot's jitter adds
        nothing; resets and teleports left out)."""
        from exp_assignment2.grading.judge.ball_track import smoothed
        pieces, total = [[]], 0.0
        for point in self.xy(model):        # a reset cuts the path: each piece alone
            if pieces[-1] and math.hypot(point[1] - pieces[-1][-1][1],
                                         point[2] - pieces[-1][-1][2]) >= RESET_JUMP:
                pieces.append([])
            pieces[-1].append(point)
        for piece in pieces:
            anchor, gone = None, 0.0
            for _, x, y in smoothed(piece):
                if anchor is None:
                    anchor = (x, y)
                    continue
                gone = math.hypot(x - anchor[0], y - anchor[1])
                if gone >= step:
                    total, anchor, gone = total + gone, (x, y), 0.0
            total += gone           # the last few cm to where it ended
        return total

    def joint_names(self, model):
        """Every moving joint of the model in the record, by name."""
        names = set()
        for state in self.states:
            names.update((state['joints'].get(model) or {}))
        return sorted(names)

    def topic(self, name, namespace=''):
        """[(t, msg)] of a recorded topic; a relative name is the robot's (``namespace``)."""
        if not name.startswith('/'):
            name = '/%s/%s' % (namespace, name) if namespace else '/' + name
        return [(t, msg) for t, topic, msg in self.topics if topic == name]

    def xy(self, model):
        """[(t, x, y)] of a model while it existed."""
        out = []
        for state in self.states:
            pose = state['models'].get(model)
            if pose and pose[0] is not None and pose[1] is not None:
                out.append((state['t'], pose[0], pose[1]))
        return out

    def angles(self, model, joint):
        """[(t, position)] of one joint of the model."""
        return [(s['t'], (s['joints'].get(model) or {}).get(joint)) for s in self.states
                if (s['joints'].get(model) or {}).get(joint) is not None]

    def distances(self, a, b):
        """[(t, planar distance)] between two models, where both were seen."""
        out = []
        for state in self.states:
            pa, pb = state['models'].get(a), state['models'].get(b)
            if pa and pb and None not in pa[:2] and None not in pb[:2]:
                out.append((state['t'], math.hypot(pa[0] - pb[0], pa[1] - pb[1])))
        return out
