"""What a person types from a README (no ROS): the code in it (fenced and
indented blocks, inline code, and plain lines that begin with ``roslaunch`` or
``rosrun``), and each command word as they type it: a word within :data:`TYPO`
letters of a command they know (one wrong, left out, added or two swapped,
each), and no command of its own, is read as that command, as the person
reading "command not found" types it again."""
import re

# the command words a person types from a README, and mistypes
TYPED = ('roslaunch', 'rosrun', 'catkin_make', 'rostopic', 'rosservice', 'source')
TYPO = 2
# commands of their own a few letters from those: never read as another
KNOWN = {'roscd', 'rosls', 'rosed', 'roscp', 'rosbag', 'rosmsg', 'rossrv', 'rosnode', 'rospack',
         'rosparam', 'roscore', 'rosdep', 'rostest', 'rosunit', 'roswtf', 'rosclean', 'rospy',
         'roscpp', 'catkin', 'cmake', 'make', 'sudo', 'course', 'resource'}
# a line of plain text that begins with a command: after a list's mark or a prompt
PLAIN = re.compile(r'^\s*(?:[-*+]\s+|\d+[.)]\s+|[$>]\s*)?([A-Za-z_]+)\s+\S+')
# a command's first word, after a shell prompt
PROMPT = re.compile(r'^(\s*(?:[^\s$#>%]*[$#>%]\s+)?)([A-Za-z_][\w-]*)(?=\s|$)')


def _distance(a, b):
    """Letters changed, left out, added or swapped (two side by side) from ``a`` to ``b``."""
    rows = [list(range(len(b) + 1))]
    for i in range(1, len(a) + 1):
        row = [i] + [0] * len(b)
        for j in range(1, len(b) + 1):
            row[j] = min(rows[-1][j] + 1, row[j - 1] + 1,
                         rows[-1][j - 1] + (a[i - 1] != b[j - 1]))
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                row[j] = min(row[j], rows[-2][j - 2] + 1)
        rows.append(row)
    return rows[-1][-1]


def command_word(word):
    """The command word a person meant by ``word`` (:data:`TYPED`), or None: the
    word itself, or the one within :data:`TYPO` letters of it when it is no command of
    its own and no other is as close."""
    if word in TYPED or word in KNOWN or len(word) < 4:
        return word if word in TYPED else None
    near = sorted((_distance(word.lower(), t), t) for t in TYPED)
    if near[0][0] <= min(TYPO, len(near[0][1]) // 3) and \
            (len(near) < 2 or near[1][0] > near[0][0]):
        return near[0][1]
    return None


def typed(segment):
    """(the segment as the person types it, the README's word it corrects or None)."""
    match = PROMPT.match(segment)
    if not match:
        return segment, None
    meant = command_word(match.group(2))
    if meant is None or meant == match.group(2):
        return segment, None
    return segment[:match.start(2)] + meant + segment[match.end(2):], match.group(2)


def code_texts(text):
    """[(code, plain)] of the README: fenced blocks' lines and inline code spans
    (``plain`` False), and lines of plain text that begin with ``roslaunch`` or
    ``rosrun`` (``plain`` True: a README written without code marks is typed as
    well; such a line runs only when it names something the run has, see
    :mod:`~exp_assignment2.grading.plan.choose`)."""
    texts, fenced = [], False
    for line in text.splitlines():
        if re.match(r'^\s*(```|~~~)', line):
            fenced = not fenced
            continue
        if fenced or line.startswith('    ') or line.startswith('\t'):
            texts.append((line, False))
            continue
        spans = re.findall(r'`([^`\n]+)`', line)
        texts.extend((span, False) for span in spans)
        bare = PLAIN.match(line)
        if not spans and bare and command_word(bare.group(1)) in ('roslaunch', 'rosrun'):
            texts.append((line[bare.start(1):].strip().rstrip('.'), True))
    return texts
