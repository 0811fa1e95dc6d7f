"""Massless URDF links as Gazebo 11 models them (plain Python: no ROS, no pybullet).

Gazebo reads a URDF through sdformat's converter (``parser_urdf.cc``), which
first lumps every link on a fixed joint into its parent (fixed-joint
reduction: masses, visuals and collisions added to the parent), then writes
the links from the root down and stops at any link with no ``<inertial>`` or
a mass of 0 (``ignition::math::equal(mass, 0)``, within 1e-6) left after
that lumping: ``urdf2sdf: link[...] has no inertia, not modeled in sdf``,
and none of the links below it either (``children links ignored``).

So, for a dynamic model:

* a massless link on a fixed joint rides on its parent, adding no mass
  (:func:`bullet_masses` tells pybullet so, which would give a link without
  ``<inertial>`` 1 kg): nothing to say, as Gazebo says nothing; the usual
  frames of a URDF (``base_footprint``, a camera's optical frame) are such;
* a massless link on a moving joint, with no mass lumped into it, is left out
  with the links below it, and so is what moves below a massless link on a
  fixed joint (Gazebo's traversal stops there): one warning line each,
  naming the link;
* a root with no mass even after lumping: Gazebo would model nothing of the
  robot; refused, naming the link, as the SDF reader refuses a massless root.
  A root called ``world`` is Gazebo's world, not a link: each link on a joint
  to it is a root of its own (left out, not refused, when it has no mass).

A static model (``<gazebo><static>``) or a kinematic one (gravity off on its
root) is never moved by forces here, so its masses are not checked. A
negative or non-finite mass is refused by :mod:`.urdf` before this.
"""
MASS_EPSILON = 1e-6         # ignition::math::equal's default tolerance
WORLD = 'world'             # a root link of this name is Gazebo's world
SAYS = "sdformat: 'has no inertia, not modeled in sdf'"


class MasslessRoot(ValueError):
    """A dynamic model whose root link has no mass, even lumped."""


def left_out(root, masses, joints):
    """The links Gazebo leaves out of a dynamic model, and one line per cut.

    :param root: the root link's name
    :param masses: link name -> its own mass (0 when it has no inertial)
    :param joints: the model's joints (``name type parent child``)
    :returns: (set of link names left out, [warning lines])
    :raises MasslessRoot: when nothing of the model would be modeled
    """
    children = {}
    for joint in joints:
        children.setdefault(joint.parent, []).append(joint)
    lumped = {}

    def lumped_mass(link):      # its own mass and that of what is fixed to it, recursively
        if link not in lumped:
            lumped[link] = masses.get(link, 0.0) + sum(
                lumped_mass(j.child) for j in children.get(link, ()) if j.type == 'fixed')
        return lumped[link]

    def below(link):
        out = []
        for joint in children.get(link, ()):
            out += [joint.child] + below(joint.child)
        return out

    if root != WORLD and lumped_mass(root) <= MASS_EPSILON:
        raise MasslessRoot(
            'link %s: the root link of a dynamic model has no mass (no <inertial>, or mass 0), '
            'nor has any link fixed to it: Gazebo would model none of the robot (%s); give it '
            'an <inertial>, or make the model static (<gazebo><static>true</static></gazebo>)'
            % (root, SAYS))
    dropped, lines = set(), []
    pending = [root]
    while pending:
        link = pending.pop(0)
        for joint in children.get(link, ()):
            child = joint.child
            if lumped_mass(child) > MASS_EPSILON:
                pending.append(child)
            elif joint.type != 'fixed' or link == WORLD:
                lost = below(child)
                dropped.update([child] + lost)
                lines.append('link %s: no mass (no <inertial>, or mass 0) on %s joint %s: '
                             'Gazebo does not model it (%s)%s; left out here too'
                             % (child, joint.type, joint.name, SAYS,
                                ', nor the links below it: ' + ', '.join(lost) if lost else ''))
            else:
                moving = _moving_below(child, children, below)
                if moving:
                    dropped.update(moving)
                    lines.append('link %s: no mass on fixed joint %s: Gazebo lumps it into link '
                                 '%s and models nothing that moves below it (%s): links %s '
                                 'left out here too' % (child, joint.name, link, SAYS,
                                                        ', '.join(moving)))
    return dropped, lines


def _moving_below(link, children, below):
    """The links that hang on a moving joint from ``link`` or from what is
    fixed to it, and every link below those."""
    moving, stack = [], [link]
    while stack:
        for joint in children.get(stack.pop(), ()):
            if joint.type == 'fixed':
                stack.append(joint.child)
            else:
                moving += [joint.child] + below(joint.child)
    return moving


def bullet_masses(root, masses, joints):
    """The masses pybullet must be given for it to move a dynamic model as
    Gazebo's fixed-joint reduction does, {link: mass}: 0 for a massless link
    that is not the root (pybullet gives a link without ``<inertial>`` 1 kg,
    Gazebo adds no mass), and :data:`ROOT_SHARE` of what is fixed to it for a
    massless root (pybullet holds a root of mass 0 in place; the mass fixed
    to it stays on its own links, where pybullet's fixed joints carry it).

    :param masses: link name -> its own mass, of the links modeled
    :param joints: the joints between those links (``type parent child``)
    """
    children = {}
    for joint in joints:
        children.setdefault(joint.parent, []).append(joint)
    out = {link: 0.0 for link, mass in masses.items()
           if mass <= MASS_EPSILON and link != root}
    if masses[root] <= MASS_EPSILON and root != WORLD:
        fixed, stack = 0.0, [root]
        while stack:
            for joint in children.get(stack.pop(), ()):
                if joint.type == 'fixed':
                    fixed += masses[joint.child]
                    stack.append(joint.child)
        out[root] = ROOT_SHARE * fixed
    return out


# A massless root's share of the mass fixed to it: enough for pybullet to let
# it move, too little to change how the robot moves
ROOT_SHARE = 1e-3
