#!/usr/bin/env python3
"""roslaunch whose exit status says whether the launch failed (tools/run main).

roslaunch exits 0 when a node marked required="true" dies (the simulator
refusing a launch argument, or crashing): the launch is over, but a script
or CI job running it cannot tell. This is roslaunch itself, run in this
process with the same arguments, plus one handler on its error log: when it
reports a required process dead, the exit status is 1 and a last line says so.
"""
import sys

import roslaunch
import roslaunch.core


def main(argv):
    required_died = []

    def on_error(msg):
        if 'REQUIRED process' in msg:
            required_died.append(msg)
    roslaunch.core.add_printerrlog_handler(on_error)
    code = 0
    try:
        roslaunch.main(['roslaunch'] + argv)
    except SystemExit as stop:
        code = stop.code if isinstance(stop.code, int) else 1
    if required_died and code == 0:
        print('[tools/run] a required node died: the launch failed (its reason is above)',
              file=sys.stderr)
        code = 1
    return code


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
