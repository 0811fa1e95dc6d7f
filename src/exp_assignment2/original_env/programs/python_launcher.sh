#!/bin/sh
# `python` and `python3` of the original-code shell (original_env/environment.py
# copies this file to both in $EXP2_ORIGINAL_BIN, first on PATH, so `python3 x.py`,
# `#!/usr/bin/env python` scripts, rosrun and roslaunch all start here).
#
# It is /usr/bin/python3, except for one case: a script (`python3 [OPTIONS]
# SCRIPT ARGS`) not of this repository ($EXP2_REPO) is started through exp2_tab_script.py
# (src/exp_assignment2/original_env/startup), which reads it as Python 2 did
# where Python 3 cannot: with Python 2's tab rule if Python 3 refuses its
# indentation, translated by 2to3's fixers if it is Python 2 code
# (exp2_py2_read.py), exactly as it is otherwise. -c, -m, -, no argument,
# --version and the like, -x, and -E/-I (which drop PYTHONPATH, so the
# original-code shell with it) go to /usr/bin/python3 as they are;
# EXP2_PY2=0 turns the translation off (then only a script with a tab in its
# indentation goes through the runner), EXP2_TAB_RULE=0 the tab rule.
PYTHON=/usr/bin/python3

[ "${EXP2_TAB_RULE:-1}" != 0 ] || [ "${EXP2_PY2:-1}" != 0 ] || exec "$PYTHON" "$@"

# Find the script: the first argument that is not an option or an option's value.
script_at=0 index=0 value_next=
for arg in "$@"; do
  index=$((index + 1))
  if [ -n "$value_next" ]; then value_next=; continue; fi
  case $arg in
    --check-hash-based-pycs) value_next=1 ;;
    --) script_at=$((index + 1)); break ;;  # the script, whatever it looks like
    -) exec "$PYTHON" "$@" ;;
    --*) exec "$PYTHON" "$@" ;;
    -*)
      flags=${arg#-}
      while [ -n "$flags" ]; do
        flag=${flags%"${flags#?}"}
        flags=${flags#?}
        case $flag in
          c|m|x|E|I|h|V|\?) exec "$PYTHON" "$@" ;;
          W|X) [ -n "$flags" ] || value_next=1; flags= ;;
        esac
      done ;;
    *) script_at=$index; break ;;
  esac
done
[ "$script_at" -gt 0 ] && [ "$script_at" -le $# ] || exec "$PYTHON" "$@"
eval "script=\${$script_at}"
[ "$script" != - ] && [ -f "$script" ] && [ -r "$script" ] || exec "$PYTHON" "$@"
# this repository's own scripts (the simulator, also as exp_assignment2_sim) are
# Python 3 and start as they are: the grader knows its simulator by its command line
case $(readlink -f -- "$script") in "${EXP2_REPO:-/nonexistent}"/*) exec "$PYTHON" "$@" ;; esac
[ "${EXP2_PY2:-1}" != 0 ] || LC_ALL=C grep -qs -e "$(printf '^[ \f]*\t')" -- "$script" \
  || exec "$PYTHON" "$@"

# The same arguments with `-c 'import exp2_tab_script; ...'` before the script
# (without a `--` before it: what follows -c CODE is never read as an option).
index=0
for arg in "$@"; do
  shift
  index=$((index + 1))
  if [ "$index" = $((script_at - 1)) ] && [ "$arg" = -- ]; then
    continue
  elif [ "$index" = "$script_at" ]; then
    set -- "$@" -c 'import exp2_tab_script; exp2_tab_script.main()' "$arg"
  else
    set -- "$@" "$arg"
  fi
done
exec "$PYTHON" "$@"
