"""What the tests of tools/original_env share: the environment outside and
inside the original-code shell, and a snippet run in Debian's python3."""
import json
import os
import subprocess
import textwrap

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ENV_DIR = os.path.join(REPO, 'tools', 'original_env')
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
    """What shell.sh sets, computed by the same helper."""
    out = subprocess.run([PYTHON, os.path.join(ENV_DIR, 'env.py'), '--json'], env=env,
                         stdout=subprocess.PIPE, universal_newlines=True, timeout=30, check=True)
    return dict(env, **json.loads(out.stdout))


def run(code, env, timeout=30):
    return subprocess.run([PYTHON, '-c', textwrap.dedent(code)], env=env, cwd='/',
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=timeout)
