"""A class for the similarity report (issue 42): submissions that share the
template and one course file most of them carry, each with code of its own,
and one (``copier``) whose own code is a disguised copy of ``original``'s:
identifiers renamed, re-indented, comments changed, functions reordered.

``make_class(dest, count)`` writes ``dest/template`` and ``dest/class/NAME``;
``make_synthetic(dest, count)`` writes a bench's class (bench/similarity.py).
"""
import os
import random
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import grading_fixtures  # noqa: E402

# code from an earlier lab that most students carry, in no template
COURSE_FILE = '''#!/usr/bin/env python3
"""Lab 3's helpers: angles and a PID."""
import math


def wrap_angle(angle):
    while angle > math.pi:
        angle -= 2.0 * math.pi
    while angle < -math.pi:
        angle += 2.0 * math.pi
    return angle


class Pid(object):
    def __init__(self, kp, ki, kd):
        self.kp, self.ki, self.kd = kp, ki, kd
        self.integral = 0.0
        self.previous = None

    def step(self, error, dt):
        self.integral += error * dt
        derivative = 0.0 if self.previous is None else (error - self.previous) / dt
        self.previous = error
        return self.kp * error + self.ki * self.integral + self.kd * derivative
'''

SHAPES = [
    '{v} = {a} * {w} + {n}',
    'if {v} > {n}:\n    {w} = {v} - {m}\nelse:\n    {w} = {v} + {m}',
    'for {i} in range({n}):\n    {v} += {i} * {m}',
    '{w} = [{i} ** {k} for {i} in range({n}) if {i} % {m}]',
    'while {v} < {n}:\n    {v} = {v} * {k} + {m}',
    '{w} = max({v}, {a} - {n}) / ({m} + abs({w}))',
    'try:\n    {v} = {a} // {m}\nexcept ZeroDivisionError:\n    {v} = {n}',
    '{w} = {{"{i}": {v}, "{a}": {n}}}',
    'with open("{a}_{n}.txt", "w") as {i}:\n    {i}.write(str({v} - {m}))',
    '{v}, {w} = {w} % {k}, ({v} << {k}) & {n}',
]
WORDS = ['speed', 'angle', 'ball', 'goal', 'dist', 'head', 'err', 'gain', 'pose', 'radius',
         'state', 'timer', 'count', 'mask', 'frame', 'limit', 'sign', 'turn']


def independent_code(rng, functions=6, statements=7):
    """Python of its own: random shapes with random constants (a person's
    code shares no passage of 25 tokens with another's but by chance)."""
    out = ['#!/usr/bin/env python3', '"""My node."""', 'import math', '']
    for number in range(functions):
        names = rng.sample(WORDS, 5)
        out.append('\n\ndef %s_%d(%s, %s):' % (rng.choice(WORDS), number, names[0], names[1]))
        for _ in range(statements):
            shape = rng.choice(SHAPES).format(
                v=names[0], w=names[1], a=names[2], i=names[3], n=rng.randint(2, 9999),
                m=rng.randint(1, 999), k=rng.randint(2, 7))
            out.append('\n'.join('    ' + line for line in shape.split('\n')))
        out.append('    return %s' % rng.choice(names[:2]))
    return '\n'.join(out) + '\n'


def disguise(text, rng):
    """The same program as a student hides a copy: every name it defines
    renamed, comments rewritten, two spaces of indentation instead of four,
    the functions in another order."""
    defined = set(re.findall(r'def (\w+)', text)) | set(re.findall(r'^\s*(\w+)\s*[+\-*/]?=',
                                                                   text, re.M))
    for params in re.findall(r'def \w+\(([^)]*)\)', text):
        defined |= {p.strip() for p in params.split(',') if p.strip()}
    for name in sorted(defined, key=len, reverse=True):
        text = re.sub(r'\b%s\b' % re.escape(name), 'my_%s_%d' % (name[::-1], rng.randint(1, 99)),
                      text)
    text = re.sub(r'"""[^"]*"""', '"""Written by me."""', text, count=1)
    text = re.sub(r'#(?!!).*', '# my own note', text)
    head, *functions = re.split(r'\n(?=\n\ndef )', text)
    rng.shuffle(functions)
    text = '\n'.join([head] + functions)
    return re.sub(r'^((?:    )+)', lambda m: '  ' * (len(m.group(1)) // 4), text, flags=re.M)


def make_template(dest):
    """The assignment's starting package: the grader fixtures' dog that works."""
    grading_fixtures._package(dest)
    return dest


def make_class(dest, count=8, seed=42):
    """(template dir, class dir): ``count`` submissions: ``original``,
    ``copier`` (its disguised copy) and ``student_N``; all carry the
    template; all but two carry the course file."""
    rng = random.Random(seed)
    template = make_template(os.path.join(dest, 'template'))
    folder = os.path.join(dest, 'class')
    names = ['original', 'copier'] + ['student_%d' % i for i in range(1, count - 1)]
    original = independent_code(rng)
    for number, name in enumerate(names):
        root = os.path.join(folder, name)
        shutil.copytree(template, root)
        with open(os.path.join(root, 'package.xml')) as f:
            text = f.read()
        with open(os.path.join(root, 'package.xml'), 'w') as f:
            f.write(re.sub(r'<name>[^<]*</name>', '<name>%s</name>' % name, text))
        own = {'original': original, 'copier': disguise(original, rng)}.get(
            name) or independent_code(rng)
        _write(root, 'scripts/brain.py', own)
        if number < count - 2:
            _write(root, 'scripts/lab_utils.py', COURSE_FILE)
    return template, folder


def make_course_template(dest):
    """A template shaped as the course's (its robot and ball's URDF, a world,
    ``launch/gazebo_world.launch``, ``scripts/go_to_point_ball.py`` and
    ``go_to_point_robot.py``), made of this package's own fixtures and nodes."""
    shutil.copytree(os.path.join(HERE, 'fixtures', 'student_pkg'), dest)
    shutil.copy(os.path.join(grading_fixtures.BASE, 'urdf', 'ball.urdf'),
                os.path.join(dest, 'urdf'))
    nodes = os.path.join(os.path.dirname(HERE), 'src', 'exp_assignment2', 'nodes')
    for name in ('go_to_point_ball.py', 'go_to_point_robot.py'):
        with open(os.path.join(nodes, name)) as f:
            _write(dest, 'scripts/' + name, f.read())
    return dest


def make_small_class(dest, seed=62):
    """(template dir, class dir) of three submissions on the course's template
    (:func:`make_course_template`), each with its node in the launch file:
    ``independent`` (code of its own), ``copy_a`` and ``copy_b`` (two
    disguises of one other class's code)."""
    rng = random.Random(seed)
    template = make_course_template(os.path.join(dest, 'template'))
    folder = os.path.join(dest, 'class')
    elsewhere = independent_code(rng, functions=10)
    own = {'independent': independent_code(rng, functions=10),
           'copy_a': disguise(elsewhere, rng), 'copy_b': disguise(elsewhere, rng)}
    for name, code in own.items():
        root = os.path.join(folder, name)
        shutil.copytree(template, root)
        _write(root, 'scripts/state_machine.py', code)
        launch = os.path.join(root, 'launch', 'gazebo_world.launch')
        with open(launch) as f:
            text = f.read()
        with open(launch, 'w') as f:
            f.write(text.replace('</launch>', '  <node name="%s" pkg="dog_pkg" '
                                 'type="state_machine.py"/>\n</launch>' % name))
    return template, folder


def make_synthetic(dest, count, seed=1):
    """A bench's class: ``count`` submissions made from the fixtures, each a
    mutated copy (the template, the course file, independent code); every
    tenth a disguised copy of the one before's core."""
    rng = random.Random(seed)
    template = make_template(os.path.join(dest, 'template'))
    folder = os.path.join(dest, 'class')
    previous = None
    for number in range(count):
        root = os.path.join(folder, 'student_%03d' % number)
        shutil.copytree(template, root)
        core = independent_code(rng, functions=4)
        if number % 10 == 9 and previous:
            core = disguise(previous, rng)
        previous = core
        _write(root, 'scripts/core.py', core)
        _write(root, 'scripts/own.py', independent_code(rng, functions=30))   # ~300 lines
        _write(root, 'scripts/lab_utils.py', COURSE_FILE)
    return template, folder


def renamed_copy(source, dest, name, rng):
    """A copy of the submission ``source`` as a student renames one: the
    package called ``name`` (package.xml, ``$(find ...)`` and ``pkg=`` in its
    launch files), its own node disguised (:func:`disguise`)."""
    shutil.copytree(source, dest)
    old = re.search(r'<name>([^<]*)</name>', open(os.path.join(source, 'package.xml')).read())
    for folder, _, files in os.walk(dest):
        for file_name in files:
            path = os.path.join(folder, file_name)
            with open(path, errors='replace') as f:
                text = f.read()
            if file_name == 'brain.py':
                text = disguise(text, rng)
            elif old:
                text = re.sub(r'\b%s\b' % re.escape(old.group(1)), name, text)
            with open(path, 'w') as f:
                f.write(text)
    return dest


def vendor(root, name='explore_lite', seed=7):
    """A public package vendored beside a submission's own (the next
    assignment's exploration package): the same in every repository that
    carries it, and used by nothing the run starts."""
    rng = random.Random(seed)
    _write(root, '%s/package.xml' % name, '<package format="2"><name>%s</name>'
           '<version>1.0.0</version></package>\n' % name)
    for number in range(4):
        _write(root, '%s/src/%s_%d.py' % (name, name, number), independent_code(rng, functions=8))
    return os.path.join(root, name)


def _write(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(text)
