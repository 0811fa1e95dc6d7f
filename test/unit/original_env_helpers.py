"""What the tests of the original-code environment (src/exp_assignment2/original_env)
share: the environment outside and inside the original-code shell, and a
snippet run in Debian's python3."""
import os
import subprocess
import textwrap

from exp_assignment2.original_env.environment import compute

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ENV_DIR = os.path.join(REPO, 'src', 'exp_assignment2', 'original_env')
PYTHON = '/usr/bin/python3'


def base_env(pythonpath=()):
    """The environment outside the original-code shell (its entries removed)."""
    env = {k: v for k, v in os.environ.items() if k not in ('DISPLAY', 'EXP2_CV2_GUI_THREAD')}
    paths = [p for p in env.get('PYTHONPATH', '').split(os.pathsep)
             if p and not p.startswith(ENV_DIR)]
    # exp_assignment2 (for minismach): the sourced workspace, else src/.
    env['PYTHONPATH'] = os.pathsep.join(list(pythonpath) + paths + [os.path.join(REPO, 'src')])
    return env


def original_env(env):
    """What shell.sh sets last (the start-up hooks, the shims), computed by the
    same function."""
    return dict(env, **compute(env))


def run(code, env, timeout=30):
    return subprocess.run([PYTHON, '-c', textwrap.dedent(code)], env=env, cwd='/',
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=timeout)
