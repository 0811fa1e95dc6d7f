"""A run's pictures for its report page (matplotlib, no display, no ROS):
the arena from above with the robot's and the ball's paths, and the head's
angle over time, of the robot, head and ball judged (``roles``:
:mod:`exp_assignment2.grading.judge.roles`, whatever the student named them). Each
returns the file it wrote, or None when the ground truth holds nothing to draw."""
import math
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

from exp_assignment2.grading.judge.metrics import RESET_JUMP  # noqa: E402


def _segments(points):
    """Runs of (x, y) with no jump (a reset) inside."""
    runs, current = [], []
    for _, x, y in points:
        if current and math.hypot(x - current[-1][0], y - current[-1][1]) > RESET_JUMP:
            runs.append(current)
            current = []
        current.append((x, y))
    if current:
        runs.append(current)
    return runs


def robot_at(trace, roles, t):
    """(x, y) of the robot at the state nearest simulated ``t`` s (None: no pose)."""
    points = trace.xy(roles.robot.name) if roles.robot.name else []
    if not points or t is None:
        return None
    return min(points, key=lambda p: abs(p[0] - t))[1:]


def top_view(trace, roles, path, size=(4.2, 4.2), marks=()):
    """The arena from above; ``marks``: [(number, t)] of the checks' moments, each a
    numbered marker where the robot was then."""
    robot = trace.xy(roles.robot.name) if roles.robot.name else []
    ball = trace.xy(roles.ball.name) if roles.ball.name else []
    if not robot and not ball:
        return None
    fig, ax = plt.subplots(figsize=size, dpi=100)
    for points, colour, label in ((ball, '#2ca02c', roles.ball.name),
                                  (robot, '#d62728', roles.robot.name)):
        for i, run in enumerate(_segments(points)):
            xs, ys = zip(*run)
            ax.plot(xs, ys, color=colour, lw=1.5, label=label if i == 0 else None)
        if points:
            ax.plot(points[0][1], points[0][2], 'o', color=colour, ms=5)
            ax.plot(points[-1][1], points[-1][2], 's', color=colour, ms=6)
    for t, name, msg in trace.topics:
        data = msg.get('data') if isinstance(msg, dict) else None
        if isinstance(data, list) and len(data) >= 2:
            ax.plot(data[0], data[1], 'x', color='#1f77b4', ms=6)
    for number, t in marks:
        where = robot_at(trace, roles, t)
        if where:
            ax.plot(where[0], where[1], 'o', ms=11, mfc='#ffeb3b', mec='#333', zorder=5)
            ax.annotate(str(number), where, ha='center', va='center', fontsize=7, zorder=6)
    ax.set_aspect('equal', adjustable='datalim')
    ax.grid(True, lw=0.3)
    ax.set_xlabel('x (m)')
    ax.set_ylabel('y (m)')
    ax.set_title('from above: o start, \u25a0 end%s' % (
        ', numbers: the checks\' moments' if marks else ''), fontsize=9)
    ax.legend(loc='best', fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path


def head_angle(trace, roles, path, size=(5.0, 2.4)):
    robot, name = roles.robot.name, roles.head.name
    angles = trace.angles(robot, name) if robot and name else []
    if not angles:
        return None
    distances = trace.distances(robot, roles.ball.name) if roles.ball.name else []
    fig, ax = plt.subplots(figsize=size, dpi=100)
    ts, values = zip(*angles)
    ax.plot(ts, [math.degrees(v) for v in values], color='#9467bd', lw=1.2, label=name)
    ax.set_xlabel('simulated time (s)')
    ax.set_ylabel('head (deg)')
    if distances:
        other = ax.twinx()
        dt, dv = zip(*distances)
        other.plot(dt, dv, color='#7f7f7f', lw=0.8, ls='--', label='to the ball (m)')
        other.set_ylabel('to the ball (m)', fontsize=8)
    ax.grid(True, lw=0.3)
    ax.legend(loc='upper left', fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path


def thumbnail(source, path, width=160):
    import cv2
    image = cv2.imread(source)
    if image is None:
        return None
    height = max(1, image.shape[0] * width // image.shape[1])
    cv2.imwrite(path, cv2.resize(image, (width, height), interpolation=cv2.INTER_AREA))
    return path


def frame_time(path):
    """The simulated s of a frame file (``<camera>_<t>.jpg``), or None."""
    try:
        return float(os.path.basename(path).rsplit('_', 1)[1][:-4])
    except (IndexError, ValueError):
        return None


def camera_frames(record_dir, roles):
    """[(t, frame file)] of the robot's camera, in time order (``record/frames/<camera>_<t>.jpg``,
    ``<camera>`` the model's and camera's names; every camera's when the robot's cannot be told)."""
    directory = os.path.join(record_dir, 'frames')
    if not os.path.isdir(directory):
        return []
    prefix = roles.camera.name.replace('/', '_') + '_' if roles.camera.name else ''
    frames = []
    for name in sorted(os.listdir(directory)):
        t = frame_time(name)
        # '<model>_<camera>_<t>.jpg': the rest after the prefix is the time alone
        if t is not None and name.startswith(prefix) and \
                not (prefix and '_' in name[len(prefix):]):
            frames.append((t, os.path.join(directory, name)))
    return sorted(frames)


def frame_at(frames, t, within=2.0):
    """The frame file of ``frames`` ([(t, file)]) nearest ``t`` s, if one is within ``within`` s."""
    if not frames or t is None:
        return None
    near = min(frames, key=lambda f: abs(f[0] - t))
    return near[1] if abs(near[0] - t) <= within else None


def chosen_frames(record_dir, trace, roles):
    """{moment: frame file} of the robot's camera for the first sight of the ball,
    the closest approach and the end, in that order (frames:
    ``record/frames/<camera>_<t>.jpg``, ``<camera>`` the model's and camera's
    names; every camera's when the robot's cannot be told)."""
    frames = camera_frames(record_dir, roles)
    if not frames:
        return {}
    chosen = {}
    if roles.ball.name:
        from exp_assignment2.vision import BallDetector
        import cv2
        detector = BallDetector()
        for t, path in frames:
            image = cv2.imread(path)
            if image is not None and detector.detect(image) is not None:
                chosen['first sight of the ball'] = path
                break
        distances = trace.distances(roles.robot.name, roles.ball.name) \
            if roles.robot.name else []
        if distances:
            t_close = min(distances, key=lambda d: d[1])[0]
            chosen['closest approach'] = min(frames, key=lambda f: abs(f[0] - t_close))[1]
    chosen['end'] = frames[-1][1]
    return chosen
