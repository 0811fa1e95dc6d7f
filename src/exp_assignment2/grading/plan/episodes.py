"""A submission's episodes (no ROS): ``--episodes N`` runs it N times, each on
its own seed of the course's ball when the profile scripts the ball
(:mod:`~exp_assignment2.grading.plan.profile_keys`), as Duckietown's episodes
and the CARLA leaderboard's routes do: the same N courses for every student.

Episode ``k`` (from 0) plays the script's ``seeds[k]`` (past the list, one
more each), or, with ``script: true``, the first seed (``--seed``) plus ``k``.
A seed the script lists as ``hidden`` is a hidden episode: it counts in the
figures and the score, and the student's page neither names its seed nor
shows its pictures (Gradescope's ``hidden``). Without a script, episodes are
repeats: each run has its own seed and the student's ball node moves the ball.
(The runner puts :func:`ball_script` in the sandbox as ``EXP2_BALL_SCRIPT``.)
"""


def default_count(profile):
    """Episodes when ``--episodes`` is not given: one per seed the script lists, else 1."""
    script = profile.get('ball_script') or {}
    return len(script.get('seeds') or ()) or 1


def episodes(profile, count, first_seed):
    """[{'index', 'seed' (the ball's; None without a script), 'visibility'}] of ``count``."""
    script = profile.get('ball_script')
    out = []
    for k in range(count):
        seed = None
        if script is not None:
            seeds = script.get('seeds')
            if not seeds:
                seed = first_seed + k
            elif k < len(seeds):
                seed = seeds[k]
            else:
                seed = seeds[-1] + k - len(seeds) + 1
        hidden = script is not None and seed in (script.get('hidden') or ())
        out.append({'index': k, 'seed': seed, 'visibility': 'hidden' if hidden else 'visible'})
    return out


def ball_script(profile, episode, duration):
    """The simulator's setting for an episode (``EXP2_BALL_SCRIPT``'s JSON, as a
    dict: :mod:`exp_assignment2.sim.ball_setting`), None without a script: the
    course written for the run's ``duration``."""
    script = profile.get('ball_script')
    if script is None or episode is None or episode.get('seed') is None:
        return None
    out = {'seed': int(episode['seed']), 'duration': float(duration)}
    if script.get('model'):
        out['model'] = script['model']
    return out


def label(name, episode, repeat, episodes_count, repeats):
    """A run's label: the submission's name, ``-eK`` (K from 1) with several
    episodes, ``-rN`` with several repeats."""
    return name + ('-e%d' % (episode['index'] + 1) if episodes_count > 1 else '') + \
        ('-r%d' % (repeat + 1) if repeats > 1 else '')
