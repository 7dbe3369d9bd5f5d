#!/usr/bin/env bash
# Puts the Python module built in build/python on the path of Debian's /usr/bin/python3 (the
# interpreter whose numpy, matplotlib and ASE are Debian's; docs/python.md): a .pth file in its
# site-packages names the directory, so `import tripack` works in any new shell and every rebuild
# is seen at once. Needs root or sudo, like scripts/install-deps.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
module_dir=$(pwd)/build/python
ls "$module_dir"/tripack/_tripack*.so >/dev/null 2>&1 || {
  echo "install-python: no module in $module_dir/tripack (run scripts/build.sh first)" >&2
  exit 1
}
site=$(/usr/bin/python3 -c 'import site; print(site.getsitepackages()[0])')
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
$SUDO mkdir -p "$site"
echo "$module_dir" | $SUDO tee "$site/tripack.pth" >/dev/null
echo "install-python: /usr/bin/python3 imports tripack from $module_dir ($site/tripack.pth)"
