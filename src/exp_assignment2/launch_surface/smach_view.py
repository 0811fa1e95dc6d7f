"""smach_viewer's stand-in (Debian has no smach_viewer): the running state
machines' states, and the active ones, from SMACH's introspection topics.

Every topic of type ``smach_msgs/SmachContainerStructure`` and
``SmachContainerStatus`` (``<server>/smach/container_structure``,
``.../container_status``, which an ``IntrospectionServer`` publishes, smach_ros'
or the shim's) is followed, as smach_viewer finds its servers. With a display
each container is drawn as a list of its states, the active ones in green,
with their transitions; the first time a container is seen, one line says
what it has. Without a display it says so in one line. It never ends on its
own: it waits until stopped.
"""
import os

import numpy as np
import rospy

from exp_assignment2.launch_surface import viewer
from exp_assignment2.launch_surface.stopping import Stop

STRUCTURE_TYPE = 'smach_msgs/SmachContainerStructure'
STATUS_TYPE = 'smach_msgs/SmachContainerStatus'
DISCOVERY = 2.0         # wall s between two looks for new introspection topics
LINE, WIDTH = 26, 640   # px


def describe(structures, statuses):
    """[(text, active)] lines for containers: ``structures`` and ``statuses``
    map a container path to its latest message (plain data, for tests)."""
    lines = []
    for path in sorted(structures):
        structure, status = structures[path], statuses.get(path)
        active = set(status.active_states) if status else set()
        lines.append(('%s  (outcomes: %s)' % (path, ', '.join(structure.container_outcomes)),
                      False))
        edges = list(zip(structure.internal_outcomes, structure.outcomes_from,
                         structure.outcomes_to))
        for child in structure.children:
            out = ', '.join('%s -> %s' % (o, t) for o, f, t in edges if f == child)
            lines.append(('  %s %s%s' % ('>' if child in active else ' ', child,
                                         '   [%s]' % out if out else ''), child in active))
    return lines


def render(lines):
    """A BGR image of :func:`describe`'s lines, the active ones green."""
    import cv2
    image = np.full((max(1, len(lines)) * LINE + 12, WIDTH, 3), 32, np.uint8)
    for index, (text, active) in enumerate(lines):
        cv2.putText(image, text, (8, (index + 1) * LINE), cv2.FONT_HERSHEY_SIMPLEX, 0.55,
                    (80, 220, 80) if active else (230, 230, 230), 1, cv2.LINE_AA)
    return image


class Introspection(object):
    """Follows every introspection topic; calls ``changed()`` on news."""

    def __init__(self, messages, changed):
        self.structure_cls, self.status_cls = messages
        self.structures, self.statuses, self.followed = {}, {}, set()
        self.changed = changed
        self.timer = rospy.Timer(rospy.Duration(DISCOVERY), self.discover)
        self.discover(None)

    def discover(self, _event):
        try:
            topics = rospy.get_published_topics()
        except Exception:       # the master went away: try again later
            return
        for topic, kind in topics:
            if topic in self.followed or kind not in (STRUCTURE_TYPE, STATUS_TYPE):
                continue
            self.followed.add(topic)
            structure = kind == STRUCTURE_TYPE
            rospy.Subscriber(topic, self.structure_cls if structure else self.status_cls,
                             self.on_message, structure, queue_size=10)

    def on_message(self, msg, structure):
        table = self.structures if structure else self.statuses
        new = structure and msg.path not in self.structures
        table[msg.path] = msg
        if new:
            rospy.loginfo('smach_viewer: showing %s: states %s', msg.path,
                          ', '.join(msg.children))
        self.changed()


def main():
    """The smach_viewer.py executable."""
    stop = Stop()
    rospy.init_node('smach_viewer', anonymous=True, disable_signals=True)
    display = viewer.display_of(os.environ)
    try:
        if display is None:
            rospy.loginfo('smach_viewer: no display (DISPLAY is not set), so no window; the '
                          'launch runs on')
        else:
            _show(display)
    except Exception as exc:        # a viewer never ends the launch
        rospy.logerr('smach_viewer: cannot show the state machines: %s; the launch runs on', exc)
    stop.wait()
    rospy.signal_shutdown('smach_viewer stopped')
    return 0


def _show(display):
    from smach_msgs.msg import SmachContainerStatus, SmachContainerStructure

    from exp_assignment2.ros.dog import ImageWindow
    window = ImageWindow('smach_viewer')
    holder = []

    def changed():
        if holder:
            window.show(render(describe(holder[0].structures, holder[0].statuses)))

    holder.append(Introspection((SmachContainerStructure, SmachContainerStatus), changed))
    window.show(render([('waiting for a state machine (its IntrospectionServer)', False)]))
    rospy.loginfo('smach_viewer: on display %s, following SMACH introspection topics', display)
