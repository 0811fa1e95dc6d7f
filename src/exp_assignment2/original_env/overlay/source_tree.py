"""What of the user's package directory counts, and how the overlay sees it.

The overlay never builds in the user's directory: its source space holds a
directory of symbolic links, one per top-level entry of the user's directory
(so an edited script is live at once), leaving out what a build or a version
control system left there. The same rule decides what the content hash, which
says when to rebuild, reads.
"""
import hashlib
import os
import shutil

# Top-level entries a catkin build or a checkout leaves in a package directory.
SKIPPED_AT_TOP = frozenset(('build', 'devel', 'install', 'logs', '.catkin_tools',
                            '.catkin_workspace'))
# Directories skipped at any depth: version control and Python's byte code.
SKIPPED_ANYWHERE = frozenset(('.git', '.hg', '.svn', '__pycache__'))
SKIPPED_SUFFIXES = ('.pyc', '.pyo')


def counted_entries(directory):
    """Top-level names of ``directory`` that belong to the package, sorted."""
    return sorted(name for name in os.listdir(directory)
                  if name not in SKIPPED_AT_TOP and name not in SKIPPED_ANYWHERE)


def content_hash(directory):
    """SHA-1 over the counted files' paths, executable bits and contents.

    Symbolic links count by their target's text, so a link loop or a link out
    of the tree is harmless.
    """
    digest = hashlib.sha1()
    for top in counted_entries(directory):
        for rel, full in _files(directory, top):
            digest.update(rel.encode('utf-8', 'surrogateescape') + b'\0')
            if os.path.islink(full):
                digest.update(b'link:' + os.readlink(full).encode('utf-8', 'surrogateescape'))
            else:
                digest.update(b'x' if os.access(full, os.X_OK) else b'-')
                with open(full, 'rb') as f:
                    for block in iter(lambda: f.read(1 << 20), b''):
                        digest.update(block)
            digest.update(b'\0')
    return digest.hexdigest()


def _files(directory, top):
    full_top = os.path.join(directory, top)
    if os.path.islink(full_top) or not os.path.isdir(full_top):
        yield top, full_top
        return
    for root, dirs, files in os.walk(full_top):
        dirs[:] = sorted(d for d in dirs if d not in SKIPPED_ANYWHERE)
        for name in sorted(files):
            if not name.endswith(SKIPPED_SUFFIXES):
                full = os.path.join(root, name)
                yield os.path.relpath(full, directory), full
        for name in dirs:       # links to directories are not walked: hash the link
            full = os.path.join(root, name)
            if os.path.islink(full):
                yield os.path.relpath(full, directory), full


def link_farm(directory, farm):
    """Make ``farm`` a directory of links to the counted entries of ``directory``.

    Whatever ``farm`` held is replaced; ``directory`` is only read.
    """
    if os.path.islink(farm) or os.path.isfile(farm):
        os.unlink(farm)
    elif os.path.isdir(farm):
        for name in os.listdir(farm):
            path = os.path.join(farm, name)
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path)
            else:
                os.unlink(path)
    os.makedirs(farm, exist_ok=True)
    for name in counted_entries(directory):
        os.symlink(os.path.join(directory, name), os.path.join(farm, name))
