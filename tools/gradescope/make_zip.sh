#!/usr/bin/env bash
# The autograder zip for Gradescope (docs/grading.md, "Gradescope"): Gradescope
# unpacks the zip's root as /autograder/source and wants setup.sh and
# run_autograder there, so the package's committed files (git archive HEAD) go at
# the root with those two beside them.
# Usage: bash tools/gradescope/make_zip.sh [OUT.zip]
set -eo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
OUT="$(realpath -m "${1:-autograder.zip}")"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
git -C "$REPO" archive --format=tar HEAD | tar -x -C "$TMP"
cp "$REPO/tools/gradescope/setup.sh" "$REPO/tools/gradescope/run_autograder" "$TMP/"
chmod +x "$TMP/setup.sh" "$TMP/run_autograder"
rm -f "$OUT"
(cd "$TMP" && /usr/bin/python3 -m zipfile -c "$OUT" ./*)
echo "$OUT"
