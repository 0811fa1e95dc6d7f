"""``libgazebo_ros_control.so``: the controllers of the user's YAML, under
the robot's namespace, as gazebo_ros_control and a controller_manager
would run them.

Every controller declared on the parameter server under ``<ns>`` (``<ns>/
<name>/type`` and its other keys) is served, whether the YAML was loaded
before the model was spawned or after (the parameter server tells the
plugin, see :mod:`.param_watch`; a YAML arrives one parameter at a time, so it
is read once the parameters have been still for 0.2 s):

* ``joint_state_controller/JointStateController``: ``<ns>/joint_states`` of
  every movable joint at ``publish_rate`` Hz of simulated time;
* ``position_controllers/``, ``effort_controllers/`` and
  ``velocity_controllers/JointPositionController``: ``<ns>/<name>/command``
  (std_msgs/Float64) is the joint's target angle, clamped to its limits;
  ``pid`` gains are accepted (the joint is position-driven here);
* ``velocity_controllers/`` and ``effort_controllers/JointVelocityController``:
  ``<ns>/<name>/command`` is the joint's velocity.

The robot namespace is the plugin's ``robotNamespace``, else the spawn's,
else the model's name (gazebo_ros_control's default). A second plugin on a
namespace another one serves (a template's ``<gazebo>`` and the student's own
in one robot) is what Gazebo makes of it: roscpp refuses its services, one
``Tried to advertise a service that is already advertised in this node``
error each, and it runs no controller; the first serves them all.

A controller naming a joint the model lacks, or of a type not listed, gets
one warning and is ignored; one with no ``joint`` yet is given 2 s more (a
loaded machine can take that long between two leaves of a YAML) before its
warning. ``<ns>/controller_manager/load_controller``,
``unload_controller``, ``switch_controller`` and ``list_controllers`` answer
as ros_control's controller manager does (``controller_manager spawner``
uses them); a controller unloaded there stays unloaded until loaded again.
"""
import threading

import rospy

from exp_assignment2.sim.plugins import param_watch
from exp_assignment2.sim.plugins.base import Plugin
from exp_assignment2.sim.plugins.controller_manager import ControllerManager
from exp_assignment2.sim.plugins.controllers import CONTROLLER_TYPES

SETTLE = 0.2      # wall s without a parameter update before the namespace is read again
PATIENCE = 2.0    # wall s more for a joint controller whose joint is not set yet
# what ros_control's ControllerManager advertises, in its constructor's order
ADVERTISED = ('list_controllers', 'list_controller_types', 'load_controller',
              'unload_controller', 'switch_controller', 'reload_controller_libraries')
SERVED = 'gazebo_ros_control namespaces'    # the engine's {namespace: plugin serving it}


class RosControlPlugin(Plugin):
    """gazebo_ros_control (see the module docstring): robotNamespace,
    controlPeriod, robotSimType (the default one is the only one here), and
    legacyModeNS as the engine's ROS release reads it: where DefaultRobotHWSim
    looks for Gazebo's joint PID gains (:attr:`pid_gains`, reported in the
    plugin's facts; the joints here are driven by the controllers' motors
    whatever gains are there)."""

    FILENAMES = ('libgazebo_ros_control.so',)
    DEFAULT_SIM = 'gazebo_ros_control/DefaultRobotHWSim'

    def default_namespace(self):
        return self.model.name      # robot_namespace_ = parent_model_->GetName()

    def load(self):
        self.ns = '/' + self.namespace if self.namespace else ''
        self.pid_gains = self.manager = None
        served = self.engine.shared(SERVED, dict)
        if self.ns in served:       # one Gazebo node: roscpp refuses, the plugin goes on
            for service in ADVERTISED:
                self.engine.log.error(
                    'model %s: plugin %s (%s): Tried to advertise a service that is already '
                    'advertised in this node [%s/controller_manager/%s] (by model %s): this '
                    'controller manager serves nothing' % (
                        self.model.name, self.name, self.filename, self.ns, service,
                        served[self.ns].model.name))
            return
        served[self.ns] = self
        if self.options.text('robotSimType', self.DEFAULT_SIM) == self.DEFAULT_SIM:
            release, legacy = self.engine.release, self.options.boolean('legacyModeNS', None)
            if legacy is None and release.reads_legacy_mode_ns:     # as Gazebo's ROS_ERROR
                self.engine.log.error(
                    '%s: missing <legacyModeNS> while using DefaultRobotHWSim, defaults to %s '
                    '(ROS %s): the joints\' PID gains are read from /gazebo_ros_control/'
                    'pid_gains, not under the robot namespace'
                    % (self.options.where, str(release.legacy_mode_ns).lower(), release.name))
            self.pid_gains = release.pid_gains_namespace(self.namespace, legacy)
        self.manager = ControllerManager(self, self.ns)
        self._lock, self._timer = threading.Lock(), None
        initial = param_watch.watch_namespace(self.ns or '/', self._on_params)
        self._discover(initial)

    def _on_params(self, key):
        # rospy's XML-RPC thread. A YAML is loaded one parameter at a time
        # (rosparam load sets each leaf): read the namespace once the burst is
        # over, so a half-loaded controller is neither started nor warned about
        with self._lock:
            self._rescan_in(SETTLE, self._rescan)

    def _rescan_in(self, seconds, rescan):
        # called with self._lock held
        if self._timer is not None:
            self._timer.cancel()
        self._timer = threading.Timer(seconds, self.engine.call_soon, (rescan,))
        self._timer.daemon = True
        self._timer.start()

    def _rescan(self, patient=True):
        try:
            params = rospy.get_param(self.ns or '/', {})
        except (KeyError, rospy.ROSException):
            return
        self._discover(params, patient)

    def _discover(self, params, patient=True):
        waiting = self.manager.discover(params if isinstance(params, dict) else {}, patient)
        if waiting:         # read once more, then warned about if still without a joint
            with self._lock:
                self._rescan_in(PATIENCE, lambda: self._rescan(patient=False))

    def facts(self):
        return dict(Plugin.facts(self), pid_gains=self.pid_gains,
                    serves=self.manager is not None)

    def before_step(self):
        if self.manager is not None:
            self.manager.apply()

    def after_step(self):
        if self.manager is not None:
            self.manager.publish()

    def reset(self):
        if self.manager is not None:
            self.manager.reset()

    def close(self):
        served = self.engine.shared(SERVED, dict)
        if served.get(self.ns) is self:
            del served[self.ns]
        if self.manager is None:
            return
        param_watch.unwatch_namespace(self.ns or '/', self._on_params)
        with self._lock:
            if self._timer is not None:
                self._timer.cancel()
        self.manager.close()


__all__ = ['RosControlPlugin', 'CONTROLLER_TYPES']
