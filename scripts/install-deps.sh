#!/usr/bin/env bash
# Installs every build dependency of tripack from Debian packages (Debian 12).
# Idempotent: skips apt entirely when all packages are already present.
set -euo pipefail
PKGS=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev        # linear algebra, sparse QR / LU for the polisher
  libcgal-dev          # exact numbers (sqrt extensions), LP solver, geometry
  libboost-dev libboost-graph-dev  # contact graphs, multiprecision (header-only)
  libgmp-dev libmpfr-dev            # multiprecision backends
  libsuitesparse-dev   # SuiteSparseQR: fast rank-revealing sparse QR for the polisher; CHOLMOD
  coinor-libclp-dev    # COIN-OR CLP, the LP solver of relax, the rigidity test, the stress certificate
  libyaml-cpp-dev      # classes.yaml and scenes
  libcli11-dev         # command line
  libfmt-dev           # formatting
  nlohmann-json3-dev   # JSON output and input
  libcairo2-dev        # packing diagrams (SVG, PNG, PDF) drawn like the paper's figures
  libsqlite3-dev       # the campaign results database (WAL: a killed campaign keeps every finished unit)
  sqlite3              # an independent reader of that database in the soak and MPI tests
  libopenmpi-dev openmpi-bin  # campaigns beyond one machine: mpirun -np P tripack campaign ...
  clang libclang-rt-14-dev    # libFuzzer + ASan/UBSan for scripts/fuzz.sh (CI runs a smoke)
  clang-format         # the format test: every source as .clang-format writes it
  fonts-dejavu-core    # the diagrams' font, named explicitly so labels look the same everywhere
  gnuplot-nox          # draws the delta(n) and accuracy plots (svg, pngcairo, pdfcairo terminals)
  libgtest-dev googletest libbenchmark-dev
  chromium             # headless browser: the test renders the explorer's index.html
  libflint-dev         # exact d(n): LLL integer relations, exact factorisation, rational polynomials
  libflint-arb-dev     # exact d(n): ball arithmetic for root isolation and the embedding checks
  libfplll-dev         # exact d(n): the LLL of integer relations (5x FLINT's at degree 64, 4,000 digits)
  pari-gp              # the independent checker of exact certificates (checker/, shares no code)
  libpari-dev          # exact d(n): number fields (a coordinate's minimal polynomial's roots in K, extensions of K)
  python3-dev pybind11-dev  # the Python module (python/): pybind11 binds the library for /usr/bin/python3
  python3-numpy python3-matplotlib  # the module's arrays and Packing.draw()
  python3-pytest       # the Python module's test suite, run by ctest
  jupyter-nbconvert python3-ipykernel  # the example notebook docs/examples/tour.ipynb runs headless in the tests
  python3-ase          # a real client of the field reads our extended XYZ back in the tests (ASE, as OVITO users script)
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
