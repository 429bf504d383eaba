#!/usr/bin/env bash
# What SIERRA needs (docs/sierra.md), apart from essaim's own set-up (scripts/setup.sh): GNU
# parallel, which runs its runs; LaTeX, which draws its graphs; graphviz for pygraphviz; SLURM
# and munge for tests/sierra's single-node cluster; and a venv of its own, .venv-sierra (its
# pins, numpy < 2, conflict with the project's). About 2 GB; idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(parallel texlive-latex-extra texlive-fonts-recommended cm-super dvipng libgraphviz-dev
          slurm-wlm munge python3-venv)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "essaim setup_sierra: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [ ! -x .venv-sierra/bin/python3 ]; then
  python3 -m venv .venv-sierra
fi
.venv-sierra/bin/python3 -m pip install -q --disable-pip-version-check -r scripts/requirements-sierra.txt
echo "essaim setup_sierra: scripts/sierra-cli runs SIERRA with essaim's engine (docs/sierra.md)"
