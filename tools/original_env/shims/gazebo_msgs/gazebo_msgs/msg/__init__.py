"""gazebo_msgs/LinkState, LinkStates, ModelState, ModelStates, generated in memory.

The definitions are gazebo_msgs' own (same fields, so the same md5sums: these
types interoperate with a real Gazebo's). genpy writes their Python code at
import, as catkin would have at build time, and it runs in memory: no files.
"""
import types as _types

import genmsg.msg_loader as _loader
from genpy.generator import msg_generator as _msg_generator
import geometry_msgs.msg as _geometry_msgs

_DEFINITIONS = {
    'LinkState': 'string link_name\ngeometry_msgs/Pose pose\n'
                 'geometry_msgs/Twist twist\nstring reference_frame\n',
    'ModelState': 'string model_name\ngeometry_msgs/Pose pose\n'
                  'geometry_msgs/Twist twist\nstring reference_frame\n',
    'LinkStates': 'string[] name\ngeometry_msgs/Pose[] pose\ngeometry_msgs/Twist[] twist\n',
    'ModelStates': 'string[] name\ngeometry_msgs/Pose[] pose\ngeometry_msgs/Twist[] twist\n',
}


def _generate(name, text):
    context = _loader.MsgContext.create_default()
    # the installed geometry_msgs types these refer to, from their own definitions
    for dep in ('Pose', 'Point', 'Quaternion', 'Twist', 'Vector3'):
        cls = getattr(_geometry_msgs, dep)
        own_text = cls._full_text.split('\n' + '=' * 80 + '\n')[0]
        context.register(cls._type, _loader.load_msg_from_string(context, own_text, cls._type))
    full_name = 'gazebo_msgs/' + name
    spec = _loader.load_msg_from_string(context, text, full_name)
    context.register(full_name, spec)
    code = '\n'.join(_msg_generator(context, spec, {}))
    module = _types.ModuleType('%s._%s' % (__name__, name))
    exec(compile(code, '<generated %s>' % full_name, 'exec'), module.__dict__)
    cls = getattr(module, name)
    cls.__module__ = __name__
    return cls


for _name, _text in _DEFINITIONS.items():
    globals()[_name] = _generate(_name, _text)

__all__ = sorted(_DEFINITIONS)
