# Sourced by tools/run and tools/original_env/shell.sh: install what is
# missing, one installer at a time. Several of these scripts start at once on a
# fresh machine (the test suite runs three workers, each may open the original
# environment): without the lock, all but one apt-get fail on dpkg's lock and
# two pip installs can write the same files.
#   install_debian LOG_PREFIX PACKAGE...   Debian packages not yet installed
#   install_pypi LOG_PREFIX MODULE SPEC    pip install SPEC for /usr/bin/python3
#                                          unless it has MODULE

_as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

_missing_debian() {
  # one dpkg-query for all of them (one each cost 0.6 s of CPU a call of tools/run);
  # it exits 1 when one is unknown to dpkg: not an error here (the callers run
  # with errexit and pipefail, which a process substitution inherits)
  local installed
  installed=$(dpkg-query -W -f='${Package} ${Status}\n' "$@" 2>/dev/null \
                | awk '$NF == "installed" {print $1}') || true
  local p
  for p in "$@"; do
    [[ $'\n'"$installed"$'\n' == *$'\n'"$p"$'\n'* ]] || printf '%s\n' "$p"
  done
}

# Runs "$@" holding the install lock (a file in the temporary directory, so a
# user with sudo takes the same one as root).
_with_install_lock() {
  local fd
  exec {fd}>>"${TMPDIR:-/tmp}/exp_assignment2-install.lock"
  flock "$fd"
  "$@"
  local rc=$?
  exec {fd}>&-
  return $rc
}

_install_debian_locked() {
  local prefix=$1; shift
  local missing
  # asked again under the lock: another installer may have just done it
  mapfile -t missing < <(_missing_debian "$@")
  [ ${#missing[@]} -eq 0 ] && return 0
  printf '[%s] installing Debian packages: %s\n' "$prefix" "${missing[*]}" >&2
  # DPkg::Lock::Timeout: wait for dpkg's lock (an unattended upgrade may hold
  # it); our own installers are kept apart by the lock above
  _as_root apt-get -o DPkg::Lock::Timeout=600 update -qq
  _as_root env DEBIAN_FRONTEND=noninteractive \
    apt-get -o DPkg::Lock::Timeout=600 install -y -qq "${missing[@]}" >/dev/null
}

install_debian() {
  local prefix=$1; shift
  [ -z "$(_missing_debian "$@")" ] && return 0
  _with_install_lock _install_debian_locked "$prefix" "$@"
}

# Whether /usr/bin/python3 has the module: found, not imported (importing
# imutils loads cv2, 0.8 s of CPU on every start of the original environment)
_has_module() {
  /usr/bin/python3 -c "import importlib.util, sys; sys.exit(importlib.util.find_spec('$1') is None)" \
    2>/dev/null
}

_install_pypi_locked() {
  local prefix=$1 module=$2 spec=$3
  _has_module "$module" && return 0
  printf '[%s] installing %s from PyPI for /usr/bin/python3\n' "$prefix" "$spec" >&2
  _as_root /usr/bin/python3 -m pip install -q --break-system-packages \
    --root-user-action=ignore "$spec"
}

install_pypi() {
  local module=$2
  _has_module "$module" && return 0
  _with_install_lock _install_pypi_locked "$@"
}
