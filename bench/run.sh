#!/usr/bin/env bash
# Brume benchmark (make bench): bash bench/run.sh BIN_DIR [bench.py options]; see bench/README.md.
set -euo pipefail
bin=${1:-build/bin}
shift || true
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
command -v python3 > /dev/null || { echo "bench: python3 is needed" >&2; exit 1; }
exec python3 "$here/bench.py" --bin "$bin" "$@"
