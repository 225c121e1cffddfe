#!/usr/bin/env bash
# Usage: run_as_user.sh COMMAND [ARGS...]
#
# Runs COMMAND as an ordinary user, for tests of file permissions (root may
# write any file, so a refusal can only be seen as someone else). As root:
# as `nobody` through setpriv, with a HOME and TMPDIR of its own. As any
# other user: as that user. Exits 77 (ctest's skip code, with the reason on
# stderr) only where no ordinary user can be had.
set -euo pipefail
if [ "$(id -u)" -ne 0 ]; then
  exec "$@"
fi
if ! command -v setpriv >/dev/null; then
  echo "SKIPPED: running as root and setpriv (util-linux) is missing, so the permission tests cannot run as a non-root user" >&2
  exit 77
fi
if ! id nobody >/dev/null 2>&1; then
  echo "SKIPPED: running as root and there is no user 'nobody' to run the permission tests as" >&2
  exit 77
fi
group=$(id -gn nobody)
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
chown nobody:"$group" "$home"
chmod 700 "$home"
# nobody must be able to reach and run COMMAND.
if ! setpriv --reuid=nobody --regid="$group" --clear-groups test -x "$1"; then
  echo "SKIPPED: $1 cannot be run by nobody (a folder on its path is private), so the permission tests cannot run as a non-root user" >&2
  exit 77
fi
HOME=$home TMPDIR=$home setpriv --reuid=nobody --regid="$group" --clear-groups "$@"
