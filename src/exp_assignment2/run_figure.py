"""Draws a :class:`~.plot_run.Run`: the world from above over a state timeline.

Matplotlib's object API with the Agg canvas: no pyplot, no display. The
layout is fixed (figure fractions below) so a picture's regions are known,
which is what the tests look at.
"""
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

from exp_assignment2 import arena, grid
from exp_assignment2.plot_run import (DOG, STATES, hidden_stretches, is_hidden, labels_at, runs,
                                      state_segments, summary)

STATE_COLOURS = {'NORMAL': '#1f77b4', 'SLEEP': '#9467bd', 'PLAY': '#ff7f0e'}
OTHER_COLOUR = '#7f7f7f'           # before the first state message, or an unknown state
BALL_COLOUR = '#00cc00'            # the ball's own green (0, 0.8, 0)
BALL_HIDDEN_COLOUR = '#556b2f'     # darker, and dotted: where the ball was out of view
WALL_COLOUR = '#404040'
PERSON_COLOUR = '#d62728'
HOME_COLOUR = '#8c564b'            # the kennel, MiRo's home
WALL_THICKNESS = 0.2               # urdf/arena.urdf
SIZE_IN, DPI = (14.0, 11.0), 100   # 1400 x 1100 px
MAP_RECT = (0.05, 0.31, 0.62, 0.60)          # left, bottom, width, height (figure fractions)
TIMELINE_RECT = (0.10, 0.06, 0.85, 0.17)
SIDE_X = 0.70                                # legend and summary, right of the map


def state_colour(label):
    """The colour a state is drawn in (paths and timeline alike)."""
    return STATE_COLOURS.get(label, OTHER_COLOUR)


def draw(run, output, home=None, person=None):
    """Writes ``run``'s picture to ``output`` (PNG, 1400 x 1100 px)."""
    figure(run, home, person).savefig(output, dpi=DPI)


def figure(run, home=None, person=None):
    """``run``'s picture as a matplotlib Figure: the world (first axes), the
    timeline (second), legend and summary on the right. ``home`` and
    ``person`` (x, y) replace scenario B's defaults."""
    fig = Figure(figsize=SIZE_IN, dpi=DPI)
    FigureCanvasAgg(fig)
    world = fig.add_axes(MAP_RECT)
    timeline = fig.add_axes(TIMELINE_RECT)
    if run.scenario == DOG:
        _draw_arena(world)
        _draw_ball(world, run.ball)
        lanes = [('ball hidden', [(a, b - a) for a, b in hidden_stretches(run.ball)],
                  BALL_HIDDEN_COLOUR)]
        scenario = 'scenario A: the dog and the ball'
    else:
        _draw_grid(world, home or grid.HOME, person or grid.PERSON, run)
        lanes = []
        scenario = 'scenario B: MiRo'
    _draw_path(world, run)
    world.set_xlabel('x [m]')
    world.set_ylabel('y [m]')
    world.set_aspect('equal')
    _draw_timeline(timeline, run, lanes)
    handles, labels = world.get_legend_handles_labels()
    fig.legend(handles, labels, loc='upper left', fontsize=11,
               bbox_to_anchor=(SIDE_X, MAP_RECT[1] + MAP_RECT[3]))
    fig.text(SIDE_X, MAP_RECT[1], summary(run), family='monospace', fontsize=9, va='bottom')
    fig.suptitle('%s  -  %.0f s of simulated time  (%s)' % (run.name, run.duration, scenario),
                 fontsize=15)
    return fig


def _draw_arena(ax):
    """Walls (inner faces at +-WALL_INNER), the goal square, the person, the kennel."""
    w, t = arena.WALL_INNER, WALL_THICKNESS
    for x, y, dx, dy in ((-w - t, w, 2 * (w + t), t), (-w - t, -w - t, 2 * (w + t), t),
                         (-w - t, -w, t, 2 * w), (w, -w, t, 2 * w)):
        ax.add_patch(Rectangle((x, y), dx, dy, color=WALL_COLOUR, lw=0))
    # one legend entry for the four wall patches
    ax.plot([], [], color=WALL_COLOUR, lw=6, label='walls (inner faces at \u00b1%.1f m)' % w)
    g = arena.GOAL_LIMIT
    ax.plot([-g, g, g, -g, -g], [-g, -g, g, g, -g], color='#b0b0b0', ls='--', lw=1,
            label='goals: x, y in [-%g, %g] m' % (g, g))
    ax.plot(*arena.PERSON, marker='P', ms=16, color=PERSON_COLOUR, ls='', label='person (seated)')
    ax.plot(*arena.KENNEL, marker='s', ms=16, color=HOME_COLOUR, ls='', label='kennel (home)')
    lim = w + t + 0.3
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.grid(True, color='#e8e8e8', lw=0.6)


def _draw_grid(ax, home, person, run):
    """The 10 x 10 grid, home, the person, gestures and arrivals."""
    ax.set_xticks(range(grid.GRID_MIN, grid.GRID_MAX + 1))
    ax.set_yticks(range(grid.GRID_MIN, grid.GRID_MAX + 1))
    ax.grid(True, color='#d8d8d8', lw=0.8)
    ax.set_xlim(grid.GRID_MIN - 0.5, grid.GRID_MAX + 0.5)
    ax.set_ylim(grid.GRID_MIN - 0.5, grid.GRID_MAX + 0.5)
    ax.plot(*home, marker='s', ms=16, color=HOME_COLOUR, ls='', label='home (%g, %g)' % tuple(home))
    ax.plot(*person, marker='P', ms=16, color=PERSON_COLOUR, ls='', alpha=0.5,
            label="person's place (%g, %g)" % tuple(person))
    for i, (t, px, py, gx, gy) in enumerate(run.gestures):
        first = i == 0
        ax.plot(px, py, marker='P', ms=16, color=PERSON_COLOUR, ls='', zorder=6,
                label='person, from /gesture' if first else None)
        ax.annotate('', xy=(gx, gy), xytext=(px, py),
                    arrowprops=dict(arrowstyle='->', color=PERSON_COLOUR, lw=1.2, ls='--'),
                    zorder=4)
        ax.plot(gx, gy, marker='*', ms=14, color=PERSON_COLOUR, ls='', zorder=6,
                label='pointed at (/gesture)' if first else None)
    if run.arrivals:
        ax.plot([a[3] for a in run.arrivals], [a[4] for a in run.arrivals], marker='o', ms=11,
                mfc='none', mec='black', mew=1.5, ls='', label='arrival (/arrival)')


def _draw_ball(ax, ball):
    """The ball's path: solid where it could be seen, dotted where it was hidden."""
    seen = {False: False, True: False}     # one legend entry each
    for hidden, xs, ys in runs(ball.x, ball.y, [is_hidden(z) for z in ball.z]):
        label = None if seen[hidden] else ('ball, hidden (z < 0 or z >= 20)' if hidden else 'ball')
        seen[hidden] = True
        ax.plot(xs, ys, color=BALL_HIDDEN_COLOUR if hidden else BALL_COLOUR,
                ls=':' if hidden else '-', lw=2.0, label=label, zorder=2)
    if ball.t:
        ax.plot(ball.x[0], ball.y[0], marker='o', ms=8, color=BALL_COLOUR, mec='black', ls='',
                label='ball start', zorder=4)


def _draw_path(ax, run):
    """The robot's path coloured by the state it was in, start and end marked."""
    robot, seen = run.robot, set()
    for label, xs, ys in runs(robot.x, robot.y, labels_at(robot.t, run.changes)):
        name = 'robot: %s' % (label or 'before the first state')
        ax.plot(xs, ys, color=state_colour(label), lw=2.8, zorder=3,
                label=None if name in seen else name)
        seen.add(name)
    if robot.t:
        ax.plot(robot.x[0], robot.y[0], marker='o', ms=10, color='white', mec='black', mew=2,
                ls='', label='robot start', zorder=5)
        ax.plot(robot.x[-1], robot.y[-1], marker='X', ms=12, color='black', ls='',
                label='robot end', zorder=5)


def _draw_timeline(ax, run, extra_lanes):
    """One lane per state (coloured bars), then e.g. the ball's hidden stretches;
    MiRo's arrivals, gestures and words as ticks."""
    segments = state_segments(run.changes, run.end)
    names = list(STATES) + sorted(set(s[2] for s in segments) - set(STATES))
    lanes = [(s, [(a, b - a) for a, b, lab in segments if lab == s], state_colour(s))
             for s in names] + list(extra_lanes)
    for i, (name, bars, colour) in enumerate(lanes):
        ax.broken_barh(bars, (i - 0.4, 0.8), color=colour)
    events = [('arrival', [a[0] for a in run.arrivals], 'o'),
              ('gesture', [g[0] for g in run.gestures], '*'),
              ('voice', [w[0] for w in run.words], 'v')]
    for name, times, marker in events:
        if times:
            lanes.append((name, None, None))
            ax.plot(times, [len(lanes) - 1] * len(times), marker=marker, ls='', color='black')
    for t, text in run.words:
        ax.annotate(text[:20], (t, len(lanes) - 1), xytext=(3, 4), textcoords='offset points',
                    fontsize=8)
    ax.set_yticks(range(len(lanes)))
    ax.set_yticklabels([lane[0] for lane in lanes])
    ax.set_ylim(len(lanes) - 0.5, -0.5)
    ax.set_xlim(run.start, max(run.end, run.start + 1.0))
    ax.set_xlabel('simulated time [s]')
    ax.grid(True, axis='x', color='#e0e0e0')
    ax.set_title('states over time', fontsize=11, loc='left')
