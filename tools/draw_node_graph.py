#!/usr/bin/env python3
"""Draws a scenario's nodes and topics, as rqt_graph shows them, from a running
system: docs/graph_dog.png and docs/graph_miro.png.

    bash tools/run shell
    /usr/bin/python3 tools/draw_node_graph.py            # both scenarios
    /usr/bin/python3 tools/draw_node_graph.py miro       # one

Each scenario is launched headless on a ROS master of its own (port 11391 for
the dog, 11392 for MiRo, or --port), left to connect for --settle wall
seconds, and its graph is read from the master (getSystemState), as rqt_graph
reads it. As rqt_graph's defaults do, /rosout, /clock and TF are left out (every
node has them), and so are the simulator's topics that no node of the
scenario uses (Gazebo's /gazebo/* interface, camera_info: docs/interfaces.md
lists them); an action's five topics are drawn as one box, from its client
to its server. Ellipses are
nodes, boxes topics; an arrow goes from a publisher to a topic and from a
topic to a subscriber. Needs only matplotlib (no graphviz): the layout is
layered left to right, as dot's.
"""
import argparse
import os
import signal
import subprocess
import sys
import time

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Ellipse, FancyArrowPatch, FancyBboxPatch  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENARIOS = {
    'dog': ('sim_world.launch', 11391, 'Scenario A: the dog and the ball (sim_world.launch)'),
    'miro': ('miro.launch', 11392, 'Scenario B: MiRo (miro.launch)'),
}
QUIET = ('/rosout', '/rosout_agg', '/clock', '/tf', '/tf_static')
SIMULATOR = '/gazebo'
ACTION_PARTS = ('goal', 'cancel', 'status', 'feedback', 'result')


def read_graph(master_uri):
    """(publishers, subscribers) as {topic: [node, ...]}, from the master."""
    import rosgraph
    master = rosgraph.Master('/draw_node_graph', master_uri=master_uri)
    pubs, subs, _ = master.getSystemState()
    return dict(pubs), dict(subs)


def action_name(topic, topics):
    """The action a topic belongs to (its namespace), when all five are there."""
    ns, _, part = topic.rpartition('/')
    if part in ACTION_PARTS and all(ns + '/' + p in topics for p in ACTION_PARTS):
        return ns
    return None


def edges_of(pubs, subs):
    """Directed edges between node names and topic names (topics keyed 't:')."""
    topics = set(pubs) | set(subs)
    edges = set()
    # the simulator's own interface that no node of the scenario uses (/gazebo/*,
    # camera_info, the raw image): listed in docs/interfaces.md, left out here
    alone = {t for t in topics
             if set(pubs.get(t, [])) | set(subs.get(t, [])) <= {SIMULATOR}}
    for table, outward in ((pubs, True), (subs, False)):
        for topic, nodes in table.items():
            if topic in QUIET or topic in alone or topic.startswith('/draw_node_graph'):
                continue
            action = action_name(topic, topics)
            # an action: the client sends goals, the server the rest; draw client -> server
            if action:
                key = 't:%s (action)' % action
                client_side = topic.endswith(('/goal', '/cancel'))
                outward_here = outward == client_side
            else:
                key, outward_here = 't:' + topic, outward
            for node in nodes:
                if node in QUIET or node.startswith('/draw_node_graph'):
                    continue
                edges.add((node, key) if outward_here else (key, node))
    return edges


def layers(vertices, edges):
    """Longest-path layering, cycles broken by a depth-first order from the
    simulator: returns each vertex's layer and the edges drawn backwards."""
    succ = {v: [] for v in vertices}
    for a, b in edges:
        succ[a].append(b)
    order, seen = [], set()

    def visit(v):
        seen.add(v)
        for w in sorted(succ[v]):
            if w not in seen:
                visit(w)
        order.append(v)
    indegree = {v: 0 for v in vertices}
    for _, b in edges:
        indegree[b] += 1
    # the simulator first: its inputs become the back edges, as dot draws it
    for v in sorted(vertices, key=lambda v: (v != SIMULATOR, indegree[v], v)):
        if v not in seen:
            visit(v)
    order.reverse()
    rank = {v: i for i, v in enumerate(order)}
    backward = {(a, b) for a, b in edges if rank[a] > rank[b]}
    layer = {v: 0 for v in vertices}
    for v in order:
        for a, b in edges:
            if a == v and (a, b) not in backward:
                layer[b] = max(layer[b], layer[a] + 1)
    return layer, backward


def routes(layer, edges, backward):
    """Each edge as a chain of vertices one layer apart (dummies in between,
    as dot puts them), from its source to its target."""
    chains = {}
    for a, b in edges:
        lo, hi = (b, a) if (a, b) in backward else (a, b)
        chain = [lo] + [('dummy', a, b, i) for i in range(layer[lo] + 1, layer[hi])] + [hi]
        for k, d in enumerate(chain[1:-1]):
            layer[d] = layer[lo] + 1 + k
        chains[(a, b)] = chain if (a, b) not in backward else chain[::-1]
    return chains


def arrange(layer, chains, passes=12):
    """Orders each layer by the barycentre of its neighbours (fewer crossings)."""
    columns = {}
    for v, i in layer.items():
        columns.setdefault(i, []).append(v)
    for col in columns.values():
        col.sort(key=str)
    neighbours = {v: [] for v in layer}
    for chain in chains.values():
        for u, w in zip(chain, chain[1:]):
            neighbours[u].append(w)
            neighbours[w].append(u)
    for n in range(passes):
        position = {v: k - (len(c) - 1) / 2.0 for c in columns.values() for k, v in enumerate(c)}
        sweep = sorted(columns) if n % 2 == 0 else sorted(columns, reverse=True)
        for i in sweep:
            columns[i].sort(key=lambda v: (sum(position[w] for w in neighbours[v])
                                           / len(neighbours[v]) if neighbours[v] else position[v]))
            position.update({v: k - (len(columns[i]) - 1) / 2.0
                             for k, v in enumerate(columns[i])})
    return columns


def label_of(v):
    return v[2:] if v.startswith('t:') else v


def width_of(v):
    if isinstance(v, tuple):
        return 0.0
    return 0.085 * len(label_of(v)) + (0.4 if v.startswith('t:') else 0.7)


def draw(edges, title, path):
    vertices = {v for e in edges for v in e}
    layer, backward = layers(vertices, edges)
    chains = routes(layer, edges, backward)
    columns = arrange(layer, chains)
    height = max(len(c) for c in columns.values())
    xy, x = {}, 0.0
    for i in sorted(columns):
        col = columns[i]
        w = max([width_of(v) for v in col] + [0.3])
        x += w / 2
        for k, v in enumerate(col):
            xy[v] = (x, ((len(col) - 1) / 2.0 - k) * 0.9)
        x += w / 2 + 0.8
    fig, ax = plt.subplots(figsize=(0.4 + x * 0.78, 1.3 + 0.62 * height))
    ax.set_title(title, fontsize=12)
    for v, (cx, cy) in xy.items():
        if isinstance(v, tuple):
            continue
        w = width_of(v)
        if v.startswith('t:'):
            ax.add_patch(FancyBboxPatch((cx - w / 2, cy - 0.2), w, 0.4, boxstyle='square,pad=0',
                                        fc='#eef3ff', ec='#3355aa', zorder=2))
        else:
            ax.add_patch(Ellipse((cx, cy), w, 0.55, fc='#fff6d8', ec='#886600', zorder=2))
        ax.text(cx, cy, label_of(v), ha='center', va='center', fontsize=8.5, zorder=3)
    for (a, b), chain in sorted(chains.items(), key=str):
        points = []
        for k, v in enumerate(chain):
            cx, cy = xy[v]
            if isinstance(v, tuple):
                points.append((cx, cy))
                continue
            # leave a box on the side the edge goes, enter one on the side it comes from
            nxt = xy[chain[k + 1]][0] if k + 1 < len(chain) else None
            prv = xy[chain[k - 1]][0] if k > 0 else None
            ref = nxt if nxt is not None else prv
            side = 1 if (ref > cx) else -1
            points.append((cx + side * width_of(v) / 2, cy))
        xs, ys = zip(*points)
        ax.plot(xs[:-1] + (xs[-1],), ys, color='#555555', lw=0.9, zorder=1)
        ax.add_patch(FancyArrowPatch(points[-2], points[-1], arrowstyle='-|>', mutation_scale=11,
                                     lw=0.9, color='#555555', zorder=1, shrinkA=0, shrinkB=0))
    xs = [p[0] for p in xy.values()]
    ys = [p[1] for p in xy.values()]
    ax.set_xlim(min(xs) - 1.3, max(xs) + 1.3)
    ax.set_ylim(min(ys) - 0.6, max(ys) + 0.6)
    ax.axis('off')
    fig.text(0.01, 0.01, 'ellipses: nodes; boxes: topics (an action\'s five as one, client to '
             'server); left out: /rosout, /clock and TF (as rqt_graph does), and the '
             'simulator\'s topics no node here uses', fontsize=7, color='#555555')
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def run_scenario(name, port, settle, out_dir):
    launch, default_port, title = SCENARIOS[name]
    port = port or default_port
    uri = 'http://localhost:%d' % port
    env = dict(os.environ, ROS_MASTER_URI=uri)
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    proc = subprocess.Popen(['roslaunch', '-p', str(port), 'exp_assignment2', launch],
                            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT,
                            start_new_session=True)
    try:
        time.sleep(settle)
        if proc.poll() is not None:
            sys.exit('%s ended early (exit %s)' % (launch, proc.returncode))
        pubs, subs = read_graph(uri)
    finally:
        os.killpg(proc.pid, signal.SIGINT)
        try:
            proc.wait(30)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    path = os.path.join(out_dir, 'graph_%s.png' % name)
    draw(edges_of(pubs, subs), title, path)
    print(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('scenarios', nargs='*', metavar='SCENARIO',
                        help='dog, miro (default: both)')
    parser.add_argument('--port', type=int, help='the master port (default: 11391, 11392)')
    parser.add_argument('--settle', type=float, default=25.0,
                        help='wall seconds to wait for every connection (default 25)')
    parser.add_argument('--out', default=os.path.join(REPO, 'docs'))
    args = parser.parse_args()
    unknown = set(args.scenarios) - set(SCENARIOS)
    if unknown:
        parser.error('unknown scenario %s; accepted: %s' % (', '.join(sorted(unknown)),
                                                             ', '.join(sorted(SCENARIOS))))
    for name in args.scenarios or sorted(SCENARIOS):
        run_scenario(name, args.port, args.settle, args.out)


if __name__ == '__main__':
    main()
