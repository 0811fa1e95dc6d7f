"""A setup file's environment, as ``source FILE`` in bash would leave it."""
import os
import subprocess

# what bash itself sets, not the setup file
_SHELL_OWN = ('_', 'SHLVL', 'PWD', 'OLDPWD')


def sourced(setup_file, environ):
    """``environ`` after ``source setup_file`` (a catkin ``setup.bash``)."""
    proc = subprocess.run(
        ['bash', '-c', 'set +u; source "$1" >&2 && exec env -0', 'bash', setup_file],
        env=environ, stdout=subprocess.PIPE, check=True)
    env = dict(item.split('=', 1) for item in proc.stdout.decode(
        'utf-8', 'surrogateescape').split('\0') if '=' in item)
    for key in _SHELL_OWN:
        if key in environ:
            env[key] = environ[key]
        else:
            env.pop(key, None)
    return env
