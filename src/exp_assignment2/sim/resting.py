"""Bodies at rest (no ROS): a dynamic model that nothing drives (no plugin, no
sensor) and with no ``allow_auto_disable`` false is put to sleep by pybullet once
it has been still for a while (a barrel, a box, the course's human), as Gazebo's
ODE auto-disables a model with no joint; a body that touches it, or a pose, a
velocity or a joint command given to it (:func:`wake`), wakes it. Asleep it costs
no physics step.
"""
from exp_assignment2.sim.bullet import p


def may_rest(model):
    """Whether ``model`` (a :class:`~.model.Model`) may be put to rest; if so, it is
    allowed to from now on."""
    gz = model.urdf.gazebo
    allowed = not (model.static or model.kinematic or gz.plugins or gz.sensors
                   or not gz.auto_disable)
    if allowed:
        p.changeDynamics(model.id, -1, activationState=p.ACTIVATION_STATE_ENABLE_SLEEPING,
                         physicsClientId=model.client)
    return allowed


def wake(model, linear=(0, 0, 0), angular=(0, 0, 0)):
    """``model`` moves again from the next step on, with the velocity it is given
    now (pybullet leaves a body at rest where it is told to be, frozen, until
    something touches it). A body at rest has no velocity at all; the first step
    of one woken wipes the velocity it is given, which it is given again after it."""
    if not model.may_rest:
        return
    lin, ang = p.getBaseVelocity(model.id, physicsClientId=model.client)
    if any(lin) or any(ang):
        return                      # awake
    p.changeDynamics(model.id, -1, activationState=p.ACTIVATION_STATE_WAKE_UP,
                     physicsClientId=model.client)
    if any(linear) or any(angular):
        model.physics.after_step(lambda: model.removed or p.resetBaseVelocity(
            model.id, list(linear), list(angular), physicsClientId=model.client))
