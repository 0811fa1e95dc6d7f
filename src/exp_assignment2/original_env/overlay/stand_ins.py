"""Catkin packages the user's CMakeLists.txt names and Debian does not have.

``find_package(catkin REQUIRED COMPONENTS gazebo_ros ...)`` stops a build
when one component is not installed. The overlay finds out which named
components CMake cannot find (asking CMake itself, the way catkin looks them
up), and gives each a stand-in: a ``<name>Config.cmake`` that is found and
provides nothing (no headers, no libraries). C++ code that includes a
stand-in's headers still fails to compile, with the compiler naming the
header. The message packages the workspace builds from tools/stand_ins
(desktop-full's actionlib_tutorials, turtlesim, ...; gazebo_msgs, motion_plan)
are found by the probe like any installed package, so they are the real
thing to CMake (their messages, headers and Python modules), never an empty
stand-in.
"""
import os
import re
import subprocess

_COMMENT = re.compile(r'#[^\n]*')
_CATKIN_FIND = re.compile(r'find_package\s*\(\s*catkin\b([^)]*)\)', re.IGNORECASE)
_KEYWORDS = frozenset(('REQUIRED', 'QUIET', 'COMPONENTS', 'OPTIONAL_COMPONENTS', 'CONFIG',
                       'NO_MODULE', 'EXACT'))

# The probe: for each name, what catkin's find_package(catkin COMPONENTS ...)
# does (catkinConfig.cmake), without stopping at the first missing one.
PROBE_CMAKE = r'''cmake_minimum_required(VERSION 3.5)
# a language, for the library architecture (lib/x86_64-linux-gnu) and find_library
project(exp2_overlay_probe C)
string(REPLACE ":" ";" _prefixes "$ENV{CMAKE_PREFIX_PATH}")
foreach(_name ${EXP2_NAMES})
  set(_paths "")
  foreach(_prefix ${_prefixes})
    if(IS_DIRECTORY ${_prefix}/share/${_name}/cmake)
      list(APPEND _paths ${_prefix}/share/${_name}/cmake)
    endif()
  endforeach()
  find_package(${_name} QUIET NO_MODULE PATHS ${_paths})
  if(${_name}_FOUND)
    message(STATUS "exp2-probe found ${_name}")
  else()
    message(STATUS "exp2-probe missing ${_name}")
  endif()
endforeach()
'''

STAND_IN_CONFIG = '''# Stand-in written by tools/original_env (--package): Debian has no {name},
# so find_package(catkin COMPONENTS {name}) finds this, which provides nothing.
set({name}_FOUND TRUE)
set({name}_VERSION "0.0.0")
set({name}_INCLUDE_DIRS "")
set({name}_LIBRARIES "")
set({name}_LIBRARY_DIRS "")
set({name}_DEFINITIONS "")
set({name}_EXPORTED_TARGETS "")
set({name}_CFG_EXTRAS "")
'''


def catkin_components(cmake_text):
    """The components of every ``find_package(catkin ... COMPONENTS ...)``, in order."""
    text = _COMMENT.sub('', cmake_text)
    names = []
    for match in _CATKIN_FIND.finditer(text):
        words = match.group(1).split()
        if 'COMPONENTS' not in words and 'OPTIONAL_COMPONENTS' not in words:
            continue
        for word in words:
            if word not in _KEYWORDS and word != 'catkin' and word not in names:
                names.append(word)
    return names


def components_of_tree(directory):
    """Catkin components named by every CMakeLists.txt in ``directory``."""
    names = []
    for root, dirs, files in os.walk(directory, followlinks=True):
        dirs[:] = sorted(d for d in dirs if not d.startswith('.'))
        if 'CMakeLists.txt' in files:
            with open(os.path.join(root, 'CMakeLists.txt'), errors='replace') as f:
                names += [n for n in catkin_components(f.read()) if n not in names]
    return names


def parse_probe(output):
    """(found, missing) from the probe's output."""
    found = re.findall(r'exp2-probe found (\S+)', output)
    missing = re.findall(r'exp2-probe missing (\S+)', output)
    return found, missing


def missing_components(names, probe_dir, environ):
    """The names CMake cannot find in this environment.

    ``None`` when the probe itself failed (a package's config stopped it):
    then the build is left to say what is wrong.
    """
    if not names:
        return []
    os.makedirs(probe_dir, exist_ok=True)
    with open(os.path.join(probe_dir, 'CMakeLists.txt'), 'w') as f:
        f.write(PROBE_CMAKE)
    build = os.path.join(probe_dir, 'build')
    proc = subprocess.run(['cmake', '-S', probe_dir, '-B', build,
                           '-DEXP2_NAMES=' + ';'.join(names)],
                          env=environ, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=300)
    found, missing = parse_probe(proc.stdout)
    if proc.returncode != 0 or set(found) | set(missing) != set(names):
        return None
    return missing


def write_stand_ins(names, prefix):
    """Write one empty catkin package config per name under ``prefix``/share."""
    for name in names:
        directory = os.path.join(prefix, 'share', name, 'cmake')
        os.makedirs(directory, exist_ok=True)
        with open(os.path.join(directory, name + 'Config.cmake'), 'w') as f:
            f.write(STAND_IN_CONFIG.format(name=name))
