"""Build the user's package in an overlay workspace: original-env --package DIR.

:func:`build` (called by :func:`exp_assignment2.original_env.environment.environment`
with the workspace sourced) builds DIR, and each ``--with MORE`` beside it
(what a class had installed besides ROS, such as a course's packages, as a
teacher's grading.yaml names them), and returns the environment with the
overlay in it; progress goes to stderr. The overlay is a catkin workspace
chained on the workspace, under ``$EXP2_OVERLAY_ROOT`` (default ``WS/overlays``),
one per directory: its source space links to DIR's files (DIR is only read),
its build and devel spaces are its own. It is rebuilt only when DIR's content
(source_tree), the main workspace or this tool changed. On the way it
installs the Debian development packages a package made from the course
template needs, and gives a stand-in to every catkin component its
CMakeLists.txt names that neither Debian nor the workspaces have (stand_ins).
A failed build raises :class:`BuildFailed` with one line naming the user's
file (build_errors).
"""
import hashlib
import os
import shutil
import subprocess
import sys

from exp_assignment2 import layout
from exp_assignment2.original_env.overlay import (build_errors, debian_packages, python_package,
                                                  sim_package, source_tree, stand_ins)
from exp_assignment2.original_env.overlay.lock import Locked
from exp_assignment2.original_env.sourcing import sourced

HERE = os.path.dirname(os.path.realpath(__file__))

OWN_PACKAGE = 'exp_assignment2'
LOCK_TIMEOUT = 3600     # s: another shell building the same overlay
BUILD_TIMEOUT = 3600
# ccache, where installed (tools/run installs it): a package built again after
# a change, or a copy of one, compiles what changed only
COMPILER_CACHE = (['-DCMAKE_C_COMPILER_LAUNCHER=ccache', '-DCMAKE_CXX_COMPILER_LAUNCHER=ccache']
                  if shutil.which('ccache') else [])


class BuildFailed(Exception):
    """The environment cannot be made: the one line to print. ``where`` (the
    user's FILE or FILE:LINE, or None) and ``message``: the first error as
    data, for a caller that shows it (the grader's driver sends it on)."""

    def __init__(self, text, where=None, message=None):
        Exception.__init__(self, text)
        self.where, self.message = where, message if message is not None else text


def log(message):
    print('[original-env] ' + message, file=sys.stderr, flush=True)


def file_hash(paths):
    digest = hashlib.sha1()
    for path in sorted(paths):
        with open(path, 'rb') as f:
            digest.update(path.encode() + b'\0' + f.read())
    return digest.hexdigest()


def overlay_dir(root, package_dir, more=()):
    key = hashlib.sha1('\0'.join((package_dir,) + tuple(more)).encode(
        'utf-8', 'surrogateescape')).hexdigest()[:10]
    return os.path.join(root, '%s-%s' % (os.path.basename(package_dir) or 'package', key))


def package_names(package_dir):
    """Names of the catkin packages in ``package_dir``; BuildFailed naming a bad package.xml."""
    from catkin_pkg.package import InvalidPackage, parse_package
    from catkin_pkg.packages import find_package_paths
    skipped = [os.path.join(package_dir, d) for d in source_tree.SKIPPED_AT_TOP]
    names = []
    for rel in find_package_paths(package_dir, exclude_paths=skipped):
        path = os.path.normpath(os.path.join(package_dir, rel))
        try:
            names.append(parse_package(path).name)
        except InvalidPackage as e:
            message = str(e).split("':", 1)[-1] if str(e).startswith('Error(s) in') else str(e)
            raise BuildFailed('%s: %s' % (os.path.join(path, 'package.xml'),
                                          build_errors.one_line(message)),
                              os.path.join(path, 'package.xml'), build_errors.one_line(message))
    if not names:
        raise BuildFailed('%s has no package.xml: give the directory of a catkin package'
                          % package_dir)
    return sorted(names)


class Overlay:
    """The overlay workspace of one user package directory."""

    def __init__(self, package_dir, workspace, root, more=(), environ=None):
        self.package_dir = package_dir
        # the environment the build runs in (the workspace sourced)
        self.environ = dict(os.environ if environ is None else environ)
        self.more = tuple(more)         # --with: more package directories beside it
        self.workspace = workspace
        self.path = overlay_dir(root, package_dir, self.more)
        self.farm = os.path.join(self.path, 'src', os.path.basename(package_dir) or 'package')
        # each --with directory in src/with_<n>_<name> (two may share a name)
        self.more_farms = [os.path.join(self.path, 'src', 'with_%d_%s' % (
            index, os.path.basename(d) or 'package')) for index, d in enumerate(self.more)]
        self.log_path = os.path.join(self.path, 'build.log')
        self.stamp_path = os.path.join(self.path, '.stamp')
        self.names_path = os.path.join(self.path, '.packages')

    def stamp(self, names):
        own = [os.path.join(HERE, f) for f in os.listdir(HERE) if f.endswith('.py')]
        # this package's launch files, as the second name rewrites them, and what it holds
        launch = [os.path.join(r, f) for r, _d, fs in os.walk(
            os.path.join(layout.PACKAGE, 'launch')) for f in fs]
        parts = [self.package_dir, ' '.join(names), source_tree.content_hash(self.package_dir),
                 ' '.join(d + '=' + source_tree.content_hash(d) for d in self.more),
                 _read(os.path.join(self.workspace, '.build_stamp')) or '', layout.ROOT,
                 file_hash(own + launch + [os.path.join(layout.PACKAGE, 'package.xml')]),
                 ' '.join(sorted(os.listdir(layout.PACKAGE)))]
        return hashlib.sha1('\n'.join(parts).encode('utf-8', 'surrogateescape')).hexdigest()

    def up_to_date(self, stamp):
        return (_read(self.stamp_path) == stamp
                and os.path.exists(os.path.join(self.path, 'devel', 'setup.bash')))

    def build(self, names, stamp):
        if os.path.exists(self.stamp_path):
            os.unlink(self.stamp_path)
        if _read(self.names_path) != ' '.join(names):   # other packages: start afresh
            for space in ('build', 'devel', 'src'):
                shutil.rmtree(os.path.join(self.path, space), ignore_errors=True)
        source_tree.link_farm(self.package_dir, self.farm)
        for directory, farm in zip(self.more, self.more_farms):
            source_tree.link_farm(directory, farm)
        debian_packages.install(debian_packages.TEMPLATE_BUILD)
        prefix = self.give_stand_ins()
        log('building %s in %s (full log: %s)' % (self.package_dir, self.path, self.log_path))
        env = dict(self.environ, CMAKE_PREFIX_PATH=os.pathsep.join(
            p for p in (prefix, self.environ.get('CMAKE_PREFIX_PATH')) if p),
                   # paths inside the overlay are hashed as relative ones: the
                   # same package in another place hits the cache
                   CCACHE_BASEDIR=self.path, CCACHE_NOHASHDIR='1')
        with open(self.log_path, 'w') as out:
            # --force-cmake: genmsg's dependency checks want a new configure
            # when a message changed, and the overlay builds only after changes
            proc = subprocess.run(['catkin_make', '-C', self.path, '--force-cmake',
                                   '-DPYTHON_EXECUTABLE=/usr/bin/python3',
                                   '-DCATKIN_ENABLE_TESTING=OFF'] + COMPILER_CACHE,
                                  stdout=out, stderr=subprocess.STDOUT, env=env,
                                  timeout=BUILD_TIMEOUT)
        if proc.returncode != 0:
            raise BuildFailed(*self.failure())
        self.write_own_package(names)
        with open(self.names_path, 'w') as f:
            f.write(' '.join(names))
        with open(self.stamp_path, 'w') as f:
            f.write(stamp)

    def give_stand_ins(self):
        """Install Debian's packages for missing components, stand-ins for the rest."""
        prefix = os.path.join(self.path, 'stand_ins')
        shutil.rmtree(prefix, ignore_errors=True)
        names = sorted(set().union(*(stand_ins.components_of_tree(f)
                                     for f in [self.farm] + self.more_farms)))
        probe = os.path.join(self.path, 'probe')
        missing = stand_ins.missing_components(names, probe, self.environ)
        candidates = [c for c in (debian_packages.candidate(n) for n in missing or ()) if c]
        if candidates:
            debian_packages.install(candidates)
            missing = stand_ins.missing_components(missing, probe, self.environ)
        if missing:
            log('stand-ins (Debian has none; found by CMake, provide nothing): '
                + ' '.join(missing))
            stand_ins.write_stand_ins(missing, prefix)
        return prefix

    def failure(self):
        with open(self.log_path, errors='replace') as f:
            found = build_errors.first_error(f.read(), self.to_user,
                                             os.path.join(self.path, 'src'))
        where, message = found or (None, 'catkin_make failed')
        return ('%s%s (full log: %s)' % (where + ': ' if where else '', message, self.log_path),
                where, message)

    def to_user(self, path):
        """The user's path of a path in the overlay's source space, else None."""
        for directory, farm in zip((self.package_dir,) + self.more,
                                   [self.farm] + self.more_farms):
            for place in (farm, os.path.realpath(farm)):
                if path == place or path.startswith(place + '/'):
                    return directory + path[len(place):]
            if path == directory or path.startswith(directory + '/'):
                return path
        return None

    def write_own_package(self, names):
        """This package as exp_assignment2_sim; one Python exp_assignment2."""
        sim_package.write_package(layout.PACKAGE,
                                  os.path.join(self.path, 'packages', sim_package.NAME),
                                  scripts=layout.SCRIPTS if layout.INSTALLED else None)
        merged = os.path.join(self.path, 'python', OWN_PACKAGE)
        shutil.rmtree(os.path.dirname(merged), ignore_errors=True)
        if OWN_PACKAGE in names:
            python_package.write_merged(merged, self.devel_python(self.path),
                                        layout.own_python_package(self.workspace))

    @staticmethod
    def devel_python(workspace):
        return os.path.join(workspace, 'devel', 'lib', 'python3', 'dist-packages', OWN_PACKAGE)

    def variables(self, names):
        """The environment with the overlay in it: its setup sourced, the
        merged package first on PYTHONPATH, this repository's second name."""
        env = sourced(os.path.join(self.path, 'devel', 'setup.bash'), self.environ)
        if OWN_PACKAGE in names:
            env['PYTHONPATH'] = os.pathsep.join(p for p in (
                os.path.join(self.path, 'python'), env.get('PYTHONPATH')) if p)
        env['ROS_PACKAGE_PATH'] = os.pathsep.join(p for p in (
            env.get('ROS_PACKAGE_PATH'), os.path.join(self.path, 'packages')) if p)
        env.update(EXP2_SIM_PACKAGE=sim_package.NAME, EXP2_OVERLAY=self.path)
        return env


def _read(path):
    try:
        with open(path) as f:
            return f.read().strip()
    except OSError:
        return None


def build(package_dir, more=(), workspace=None, root=None, environ=None):
    """Build ``package_dir`` (and the ``more`` directories beside it) in its
    overlay and return ``environ`` (the workspace sourced) with the overlay in
    it; :class:`BuildFailed` with the one line to print if it cannot be."""
    environ = dict(os.environ if environ is None else environ)
    for given, option in [(package_dir, '--package')] + [(d, '--with') for d in more]:
        if not os.path.isdir(given):
            raise BuildFailed('%s %s: no such directory' % (option, given))
    package_dir = os.path.realpath(package_dir)
    unique = []
    for directory in (os.path.realpath(d) for d in more):
        if directory not in unique + [package_dir]:
            unique.append(directory)
    more = unique
    workspace = os.path.realpath(workspace)
    root = root or environ.get('EXP2_OVERLAY_ROOT') or os.path.join(workspace, 'overlays')
    try:
        names = package_names(package_dir)
        more_names = [n for d in more for n in package_names(d)]
        twice = sorted(set(n for n in names + more_names if (names + more_names).count(n) > 1))
        if twice:
            raise BuildFailed('two packages are called %s: give each once (--package, --with)'
                              % ', '.join(twice))
        overlay = Overlay(package_dir, workspace, os.path.realpath(root), more, environ)
        for outside in [package_dir, layout.ROOT] + more:
            if overlay.path == outside or overlay.path.startswith(outside + '/'):
                raise BuildFailed('the overlay %s would be inside %s: set EXP2_OVERLAY_ROOT'
                                  ' to a directory outside it' % (overlay.path, outside))
        with Locked(os.path.join(overlay.path, '.lock'), LOCK_TIMEOUT, log):
            stamp = overlay.stamp(names + more_names)
            if overlay.up_to_date(stamp):
                log('overlay %s is up to date with %s' % (overlay.path, package_dir))
            else:
                overlay.build(names + more_names, stamp)
    except (BuildFailed, debian_packages.InstallFailed) as e:
        raise BuildFailed('the build of %s failed: %s' % (package_dir, e),
                          getattr(e, 'where', None), getattr(e, 'message', str(e)))
    except TimeoutError as e:     # the lock (another build of this overlay)
        raise BuildFailed('the build of %s failed: %s' % (package_dir, e))
    except subprocess.TimeoutExpired as e:
        raise BuildFailed('the build of %s failed: %s took more than %d s'
                          % (package_dir, e.cmd[0], e.timeout))
    log('package %s from %s%s; this repository\'s package: %s'
        % (', '.join(names), package_dir, ''.join(
            '; with %s from %s' % (', '.join(package_names(d)), d) for d in more),
           sim_package.NAME))
    return overlay.variables(names + more_names)
