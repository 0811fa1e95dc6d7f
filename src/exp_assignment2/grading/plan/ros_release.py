"""The ROS release a submission runs in, as its student ran it (no ROS).

The simulator plays Gazebo's ROS plugins as each release had them
(:mod:`exp_assignment2.sim.releases`: Kinetic's diff drive honours
``legacyMode`` and swaps the wheels; Kinetic and Melodic prefix frames with
the robot's namespace...), and a student steered for what they saw. A
submission's release is, in this order (:func:`choose`):

1. ``grading.yaml``'s for it (``submissions: NAME: release: kinetic``);
2. what the submission says: a Dockerfile's ``FROM ros:kinetic...``, its
   README naming a release (``ROS Kinetic``, ``/opt/ros/melodic``, ``Gazebo
   7``, ``Ubuntu 20.04``), catkin's own link into ``/opt/ros/RELEASE``;
3. the course's first (``grading.yaml``'s ``release``, else the profile's).

When the run's checks fail in a release it was not told, it is run again in
the next release the course allows whose behaviour differs for it
(:func:`differs`: judged from the submission's own robot and code), and the
better run counts (:func:`counted`).
"""
import collections
import os
import re

from exp_assignment2.sim import releases as sim_releases
from exp_assignment2.grading.entry.reading import read_text

NAMES = tuple(sim_releases.RELEASES)
# a release's name, or what only that release had: its Gazebo, its Ubuntu
SIGNS = [(re.compile(r'\b%s\b' % name, re.I), name) for name in NAMES] + [
    (re.compile(r'\bgazebo\s*-?\s*7\b', re.I), 'kinetic'),
    (re.compile(r'\bgazebo\s*-?\s*9\b', re.I), 'melodic'),
    (re.compile(r'\bgazebo\s*-?\s*11\b', re.I), 'noetic'),
    (re.compile(r'\bubuntu\s*16\.04\b', re.I), 'kinetic'),
    (re.compile(r'\bubuntu\s*18\.04\b', re.I), 'melodic'),
    (re.compile(r'\bubuntu\s*20\.04\b', re.I), 'noetic')]
DOCKER_FROM = re.compile(r'^\s*FROM\s+\S*?ros[^\s:]*:(\w+)', re.I | re.M)
OPT_ROS = re.compile(r'/opt/ros/(\w+)/')
README = re.compile(r'^readme(\.\w+)?$', re.I)
ROBOT_FILES = ('.urdf', '.xacro', '.gazebo', '.sdf', '.world')
PLUGIN = re.compile(r'<plugin\b[^>]*filename\s*=\s*["\']libgazebo_ros_diff_drive\.so["\']'
                    r'.*?</plugin>', re.S)
TAG = '<%s>\\s*([^<]*?)\\s*</%s>'
USES_FRAMES = re.compile(r'lookupTransform|lookup_transform|TransformListener|tf2_ros\.Buffer'
                         r'|waitForTransform|\.frame_id\b|child_frame_id')


def _files(root, keep, depth=6):
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if not d.startswith('.')]
        if dirpath[len(root):].count(os.sep) >= depth:
            dirnames[:] = []
        for name in sorted(filenames):
            if keep(name):
                yield os.path.join(dirpath, name)


def _own(root, package_dir, keep, depth=6):
    """The submission's own files that ``keep`` takes: never inside another package
    than the graded one (a vendored package's README names the release it was
    written for, not the one the student used)."""
    package_dir = os.path.normpath(package_dir or root)
    for path in _files(root, keep, depth):
        folder = os.path.dirname(path)
        while os.path.normpath(folder) != os.path.normpath(root) and \
                os.path.normpath(folder) != package_dir:
            if os.path.isfile(os.path.join(folder, 'package.xml')):
                break
            folder = os.path.dirname(folder)
        else:
            yield path


def said(root, notes=(), package_dir=None):
    """(release, why) the submission names, or (None, None): a Dockerfile's
    image first, then its READMEs' words (the most named; a tie, the first),
    then catkin's link into /opt/ros (its note, the link being left out). Only the
    submission's own files say it: none inside another package than the graded
    one (``package_dir``)."""
    for path in _own(root, package_dir,
                     lambda n: n == 'Dockerfile' or n.startswith('Dockerfile.')):
        match = DOCKER_FROM.search(read_text(path))
        if match and match.group(1).lower() in NAMES:
            return match.group(1).lower(), 'its %s says FROM %s' % (
                os.path.relpath(path, root), match.group(0).split(None, 1)[1].strip())
    counts, first = collections.Counter(), {}
    for path in _own(root, package_dir, README.match, depth=3):
        text = read_text(path)
        for sign, name in SIGNS:
            for match in sign.finditer(text):
                counts[name] += 1
                first.setdefault(name, (match.start(), os.path.relpath(path, root),
                                        match.group(0)))
    if counts:
        best = max(counts.values())
        name = min((n for n in counts if counts[n] == best), key=lambda n: first[n][:2])
        return name, 'its %s says "%s"' % (first[name][1], first[name][2])
    for note in notes:
        match = OPT_ROS.search(note)
        if match and match.group(1) in NAMES:
            return match.group(1), 'its catkin workspace was made in ROS %s (%s)' % (
                match.group(1).capitalize(), note.split(':')[0])
    return None, None


def features(root, fallback_robot=None):
    """What of the submission a release's plugins change: its diff drives'
    ``legacyMode`` values (None: no tag), whether one reads encoders, and
    whether its code reads frames. The course robot's files (``fallback_robot``)
    stand for a submission that brings no diff drive of its own."""
    legacy, encoder = [], False
    for path in _files(root, lambda n: n.endswith(ROBOT_FILES)):
        for block in PLUGIN.findall(read_text(path)):
            tag = re.search(TAG % ('legacyMode', 'legacyMode'), block)
            legacy.append(tag.group(1) if tag else None)
            source = re.search(TAG % ('odometrySource', 'odometrySource'), block)
            encoder = encoder or bool(source and source.group(1).lower() == 'encoder')
    if not legacy and fallback_robot:
        return dict(features(fallback_robot), frames=_reads_frames(root))
    return {'legacy_mode': legacy, 'encoder': encoder, 'frames': _reads_frames(root)}


def _reads_frames(root):
    return any(USES_FRAMES.search(read_text(p)) for p in _files(
        root, lambda n: n.endswith(('.py', '.cpp', '.cc', '.h', '.hpp')) or '.' not in n))


def differs(a, b, found):
    """Would a submission with these ``features`` behave otherwise in release
    ``a`` than in ``b``? The wheels' order, the odometry's twist (encoders),
    the frames' names (code that reads them)."""
    ra, rb = sim_releases.release(a), sim_releases.release(b)
    for text in found['legacy_mode']:
        value_a, _ = ra.boolean(text, ra.legacy_mode)
        value_b, _ = rb.boolean(text, rb.legacy_mode)
        if ra.swaps_wheels(value_a if text is not None else None) != \
                rb.swaps_wheels(value_b if text is not None else None):
            return True
    if found['encoder'] and ra.encoder_twist_in_child_frame != rb.encoder_twist_in_child_frame:
        return True
    return bool(found['frames'] and found['legacy_mode'] and
                ra.prefix_frames_with_namespace != rb.prefix_frames_with_namespace)


def choose(allowed, first, teacher_choice, root, notes=(), fallback_robot=None,
           package_dir=None):
    """{'release', 'why', 'next'}: the release a submission first runs in
    and why, and the allowed releases (in the course's order) to try next
    when its checks fail there, those whose behaviour differs for it; none
    to try when it was told (grading.yaml, or the submission itself)."""
    if teacher_choice:
        return {'release': teacher_choice, 'why': 'grading.yaml names it', 'next': []}
    name, why = said(root, notes, package_dir)
    if name and name in allowed:
        return {'release': name, 'why': why, 'next': []}
    found = features(root, fallback_robot)
    others = [r for r in allowed if r != first and differs(first, r, found)]
    unique = []
    for other in others:        # two that behave alike for it: the first of them only
        if not any(not differs(other, u, found) for u in unique):
            unique.append(other)
    return {'release': first, 'why': ('the course\'s first (%s names %s, which the course '
                                      'does not allow)' % (why, name)) if name else
            'the course\'s first: the submission names none', 'next': unique}


def counted(runs, score):
    """(the runs that count, the others): of a submission run in several
    releases, those of the release whose runs score best (the median; a tie,
    the one run first); ``score(run)`` is a run's score (None: no score)."""
    by_release = collections.OrderedDict()
    for run in runs:
        by_release.setdefault(run.get('release'), []).append(run)
    if len(by_release) < 2:
        return list(runs), []

    def median(group):
        values = sorted(s for s in (score(r) for r in group) if s is not None)
        return values[(len(values) - 1) // 2] if values else -1.0
    best = max(by_release, key=lambda r: (median(by_release[r]),
                                          -list(by_release).index(r)))
    return by_release[best], [r for r in runs if r.get('release') != best]
