#!/usr/bin/env bash
# Installs what Impact needs from Debian's packages; does nothing when all are there.
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libginac-dev libcln-dev          # symbolic and arbitrary-precision arithmetic
  libboost-test-dev                # tests
  libfmt-dev                       # formatting
  libtomlplusplus-dev              # derivation files
  libcli11-dev                     # the command line
  nlohmann-json3-dev               # derivations.json
  libssl-dev                       # SHA-256 (OpenSSL's libcrypto): the cache's entries named and checked
  z3 libz3-dev                     # every proof re-checked by Z3 (libz3 in-process; z3 runs output/proofs/*.smt2)
  clang libclang-rt-14-dev         # the fuzzer (libFuzzer) and sanitized builds in CI; batch loops vectorised by Clang
  g++-aarch64-linux-gnu qemu-user  # batch loops vectorised for AArch64, its kernel tests run there (kernels_aarch64)
  libbenchmark-dev                 # the kernels' benchmark (built on demand)
  texlive-latex-recommended        # pdflatex, amsmath: output/report.pdf and its test
  texlive-latex-extra              # longtable, booktabs and the rest of the report's packages
  texlive-pictures                 # pgfplots (Figs. 2 and 3)
  latexmk                          # building a report by hand
  poppler-utils                    # pdftoppm, pdffonts: the report's pages; pdftocairo: the web report's figures as SVG
  nodejs libjs-katex               # the web report (output/html): its formulas typeset by KaTeX when written
  chromium                         # the web report read in a real browser (test_web)
  locales                          # de_DE.UTF-8: the tests regenerate under a locale other than C
  python3-sympy bc                 # tests/benchmarks/engine_speed.sh: SymPy beside Impact on the 3D rough spheres
  python3-dev pybind11-dev python3-numpy  # the Python package impact (docs/python.md)
  python3-pytest                   # its tests (test_python)
  python3-nbconvert python3-ipykernel python3-matplotlib  # its notebook, run by a test
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
if [ ${#missing[@]} -ne 0 ]; then
  echo "scripts/setup.sh: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The German locale the tests run under (output must not depend on the locale).
if ! locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$'; then
  echo "scripts/setup.sh: generating the locale de_DE.UTF-8"
  $sudo localedef -i de_DE -f UTF-8 de_DE.UTF-8
fi
