"""``plot_run.py BAG [-o PNG]``: draws a recorded run as a picture: the bag
read into a Run (:mod:`exp_assignment2.plot_run`), drawn by
:mod:`exp_assignment2.run_figure`."""
import argparse
import os
import sys

from exp_assignment2.plot_run import PlotError, read_run, summary


def parse_args(argv):
    """The command line."""
    parser = argparse.ArgumentParser(
        prog='plot_run.py', description='Draw a recorded run (rosbag from record:=true) as a PNG: '
        'the world from above, paths coloured by state, and a state timeline.')
    parser.add_argument('bag', help='the bag file (sim_world.launch or miro.launch, record:=true)')
    parser.add_argument('-o', '--output', help='the PNG to write (default: BAG with .png)')
    parser.add_argument('--home', nargs=2, type=float, metavar=('X', 'Y'),
                        help="scenario B: MiRo's home, if not /home_posx, /home_posy's default")
    parser.add_argument('--person', nargs=2, type=float, metavar=('X', 'Y'),
                        help="scenario B: the person's place when no gesture says otherwise")
    return parser.parse_args(argv)


def main(argv=None):
    """Reads the bag, prints the summary, writes the picture. Exits 2 on a bag
    it cannot draw, 1 when the picture cannot be written."""
    args = parse_args(sys.argv[1:] if argv is None else argv)
    output = args.output or os.path.splitext(args.bag)[0] + '.png'
    try:
        run = read_run(args.bag)
    except PlotError as e:
        sys.stderr.write('plot_run.py: error: %s\n' % e)
        raise SystemExit(2)
    print(summary(run))
    from exp_assignment2 import run_figure    # matplotlib only once there is something to draw
    try:
        run_figure.draw(run, output, home=args.home, person=args.person)
    except (IOError, OSError) as e:
        sys.stderr.write('plot_run.py: error: cannot write %s: %s\n' % (output, e))
        raise SystemExit(1)
    print('wrote %s' % output)
    return 0
