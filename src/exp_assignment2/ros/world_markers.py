"""The world in rviz: ``~world_markers`` (visualization_msgs/MarkerArray,
latched) of the simulator node, in the ``odom`` frame: every static model's
visuals (walls, the person, the kennel, MiRo's home) and the floor grid,
from :mod:`exp_assignment2.sim.world_shapes`. Published again whenever the
scenery changes (a model spawned, deleted or moved, e.g. MiRo's person when
a gesture puts them elsewhere)."""
import rospy
from geometry_msgs.msg import Point
from std_msgs.msg import ColorRGBA
from visualization_msgs.msg import Marker, MarkerArray

from exp_assignment2.sim import world_shapes
from exp_assignment2.sim.poses import from_matrix

KINDS = {'box': Marker.CUBE, 'cylinder': Marker.CYLINDER, 'sphere': Marker.SPHERE,
         'capsule': Marker.CYLINDER, 'mesh': Marker.MESH_RESOURCE}
GRID_COLOUR = ColorRGBA(0.35, 0.35, 0.38, 1.0)
CHECK_EVERY = 20          # steps between looks at the scenery (0.2 s of simulated time)


def shape_marker(shape, frame, ident):
    """A Marker of one :class:`~exp_assignment2.sim.world_shapes.Shape`."""
    m = Marker(type=KINDS[shape.kind], action=Marker.ADD, id=ident, ns=shape.model)
    m.header.frame_id = frame
    (m.pose.position.x, m.pose.position.y, m.pose.position.z), q = from_matrix(shape.pose)
    m.pose.orientation.x, m.pose.orientation.y, m.pose.orientation.z, m.pose.orientation.w = q
    p = shape.params
    if shape.kind == 'box':
        m.scale.x, m.scale.y, m.scale.z = p['size']
    elif shape.kind in ('cylinder', 'capsule'):
        m.scale.x = m.scale.y = 2.0 * p['radius']
        m.scale.z = p['length'] + (2.0 * p['radius'] if shape.kind == 'capsule' else 0.0)
    elif shape.kind == 'sphere':
        m.scale.x = m.scale.y = m.scale.z = 2.0 * p['radius']
    else:
        m.mesh_resource = 'file://' + p['filename']
        m.scale.x, m.scale.y, m.scale.z = p['scale']
    m.color = ColorRGBA(*shape.rgba)
    return m


def world_markers(models, frame='odom'):
    """The MarkerArray of the scenery among ``models``."""
    markers = [shape_marker(s, frame, i) for i, s in enumerate(world_shapes.shapes(models))
               if s.kind in KINDS]
    lines = world_shapes.grid_lines(models)
    if lines:
        grid = Marker(type=Marker.LINE_LIST, action=Marker.ADD, id=len(markers), ns='grid',
                      color=GRID_COLOUR)
        grid.header.frame_id = frame
        grid.pose.orientation.w = 1.0
        grid.scale.x = 0.03
        grid.points = [Point(*end) for segment in lines for end in segment]
        markers.append(grid)
    # a fresh array replaces whatever rviz shows: DELETEALL first
    return MarkerArray(markers=[Marker(action=Marker.DELETEALL)] + markers)


class WorldMarkers(object):
    """Publishes the scenery once, then again when it changes (a step listener)."""

    def __init__(self, engine, frame='odom'):
        self.engine, self.frame = engine, frame
        self.pub = rospy.Publisher('~world_markers', MarkerArray, queue_size=1, latch=True)
        self.shown, self.steps = None, 0
        engine.step_listeners.append(self._look)
        self._look(engine, force=True)

    def _look(self, engine, force=False):
        self.steps += 1
        if not force and self.steps % CHECK_EVERY:
            return
        models = list(engine.models.values())
        now = (engine.generation, world_shapes.signature(models))
        if now != self.shown:
            self.shown = now
            self.pub.publish(world_markers(models, self.frame))
