"""What a submission's build and run need from Debian, known before any run
starts (rosdep's job, on the teacher's side; no ROS).

Each package a run builds names what it needs: ``package.xml``'s
dependencies (rosdep keys: ROS package names, or system keys such as
``python-numpy`` or ``eigen``) and its ``CMakeLists.txt``'s ``find_package``
(catkin components, and other CMake packages such as ``OpenCV``). What the
run's machine already has (Debian's ROS, the workspace, this package's
stand-ins, the submission's own packages) needs nothing. For the rest,
Debian's own names are tried, as Debian packages ROS: ``lib<name>-dev``
(C++ headers and CMake files), ``python3-<name>``, ``ros-<name>`` (messages'
definitions). Those that exist are installed once for the class, as root,
outside every sandbox (:func:`install`; a sandbox never installs); a key none
of them matches is said as rosdep says it (``Cannot locate rosdep definition
for [KEY]``): a note on the page, and in the reason when the build fails.
"""
import os
import re
import subprocess

from exp_assignment2.original_env.overlay import stand_ins
from exp_assignment2.grading.entry.reading import read_text

MAX_PER_SUBMISSION = 40       # Debian packages one submission may ask for
DEBIAN_NAME = re.compile(r'^[a-z0-9][a-z0-9+.-]+$')
# rosdep's system keys whose Debian name is not the key itself (Python 3, bookworm)
SYSTEM_KEYS = {
    'eigen': ['libeigen3-dev'], 'boost': ['libboost-dev'], 'opencv2': ['libopencv-dev'],
    'opencv3': ['libopencv-dev'], 'opencv': ['libopencv-dev'], 'libopencv-dev': ['libopencv-dev'],
    'python-opencv': ['python3-opencv'], 'python3-opencv': ['python3-opencv'],
    'python-imaging': ['python3-pil'], 'python-yaml': ['python3-yaml'],
    'python-rospkg': ['python3-rospkg'], 'python-catkin-pkg': ['python3-catkin-pkg'],
    'python-tk': ['python3-tk'], 'yaml-cpp': ['libyaml-cpp-dev'], 'tinyxml': ['libtinyxml-dev'],
    'tinyxml2': ['libtinyxml2-dev'], 'pcl': ['libpcl-dev'], 'libpcl-all-dev': ['libpcl-dev'],
}
# CMake packages found outside catkin: find_package(NAME) -> Debian's package
CMAKE_PACKAGES = {
    'opencv': ['libopencv-dev'], 'eigen3': ['libeigen3-dev'], 'eigen': ['libeigen3-dev'],
    'boost': ['libboost-dev'], 'pcl': ['libpcl-dev'], 'yaml-cpp': ['libyaml-cpp-dev'],
    'gazebo': [], 'pkgconfig': ['pkg-config'], 'threads': [], 'pythonlibs': ['python3-dev'],
    'pythoninterp': [], 'python3': [], 'python': [], 'catkin': [], 'gtest': [],
}
_OTHER_FIND = re.compile(r'find_package\s*\(\s*([A-Za-z0-9_.+-]+)', re.IGNORECASE)


def keys_of(package):
    """[(key, 'ros'|'cmake')] a package asks for: package.xml's keys, its
    catkin components, its other CMake packages."""
    keys = [(k, 'ros') for k in package.depends]
    cmake = read_text(os.path.join(package.path, 'CMakeLists.txt'))
    keys += [(k, 'ros') for k in stand_ins.catkin_components(cmake) if (k, 'ros') not in keys]
    for name in _OTHER_FIND.findall(re.sub(r'#[^\n]*', '', cmake)):
        if name != 'catkin' and (name, 'cmake') not in keys:
            keys.append((name, 'cmake'))
    return keys


def candidates(key, kind):
    """Debian's names to try for a rosdep key or a CMake package."""
    if kind == 'cmake':
        lower = key.lower()
        return CMAKE_PACKAGES.get(lower, ['lib%s-dev' % lower.replace('_', '-')])
    if key in SYSTEM_KEYS:
        return SYSTEM_KEYS[key]
    if key.startswith(('python-', 'python3-')):
        return ['python3-' + key.split('-', 1)[1]]
    if key.startswith('lib') or key.endswith('-dev'):
        return [key]
    name = key.replace('_', '-').lower()
    return ['lib%s-dev' % name, 'python3-%s' % name, 'ros-%s' % name]


def available_debian():
    """The names of every package apt knows (one call: ``apt-cache pkgnames``)."""
    try:
        out = subprocess.run(['apt-cache', 'pkgnames'], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, universal_newlines=True,
                             timeout=120).stdout
    except (OSError, subprocess.TimeoutExpired):
        return set()
    return set(out.split())


def resolve(built, provided, known):
    """({'debian': [names], 'unresolved': {package: [keys]}, 'notes': [...]})
    for the built :class:`~exp_assignment2.grading.entry.packages.Package` list: ``provided``, the
    names the run has without installing (ROS packages, the submission's own); ``known``,
    apt's package names."""
    debian, unresolved = [], {}
    for package in built:
        for key, kind in keys_of(package):
            if kind == 'ros' and key in provided:
                continue
            if kind == 'cmake' and key.lower() in ('catkin',):
                continue
            names = [n for n in candidates(key, kind) if DEBIAN_NAME.match(n) and n in known]
            if not names and candidates(key, kind):
                unresolved.setdefault(package.name, []).append(key)
            debian.extend(n for n in names if n not in debian)
    notes = []
    if len(debian) > MAX_PER_SUBMISSION:
        notes.append('its packages ask for %d Debian packages: the first %d installed'
                     % (len(debian), MAX_PER_SUBMISSION))
        debian = debian[:MAX_PER_SUBMISSION]
    for package, keys in sorted(unresolved.items()):
        notes.append('rosdep: %s: Cannot locate rosdep definition for [%s] (no Debian package '
                     'here; a build that needs it fails)' % (package, '], ['.join(keys)))
    return {'debian': debian, 'unresolved': unresolved, 'notes': notes}


def install(names, log):
    """The missing ones of ``names`` installed (as root, else through sudo),
    one installer at a time; a failure is one line, never an exception."""
    from exp_assignment2.original_env.overlay import debian_packages
    missing = debian_packages.missing(names) if names else []
    if not missing:
        return None
    log('installing what the submissions need from Debian: %s' % ' '.join(missing))
    try:
        debian_packages.install(missing)
    except (debian_packages.InstallFailed, OSError) as exc:
        log('could not install them: %s' % exc)
        return str(exc)
    return None


def said_by_rosdep(reason, notes):
    """A failed build's reason, with rosdep's line for a dependency it names
    that could not be had (``...: rosdep: dog: Cannot locate rosdep definition
    for [pcl_ros]``)."""
    for note in notes:
        if not note.startswith('rosdep: '):
            continue
        line = note.split(' (no Debian package')[0]
        keys = re.findall(r'\[([^\]]+)\]', line)
        if any(k.lower() in reason.lower() for k in keys) and line not in reason:
            reason += '; ' + line
    return reason
