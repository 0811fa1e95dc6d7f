#!/usr/bin/env bash
# Gradescope's setup.sh (docs/grading.md, "Gradescope"): the autograder zip holds
# this package as /autograder/source; it installs as the README says (tools/run
# setup), then what grade needs (the sandbox, the students' build dependencies):
# grade --help sets all of it up and grades nothing.
set -eo pipefail
cd /autograder/source
bash tools/run setup
bash tools/run grade --help > /dev/null
