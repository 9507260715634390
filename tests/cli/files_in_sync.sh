#!/usr/bin/env bash
# examples/rv1.prm and doc/parameters.md are what `servodrift params' prints; regenerate them with
#   build/servodrift params > examples/rv1.prm
#   build/servodrift params --format markdown > doc/parameters.md
set -eu
servodrift=$1 source=$2
diff <("$servodrift" params) "$source/examples/rv1.prm" || { echo "examples/rv1.prm is out of date"; exit 1; }
diff <("$servodrift" params --format markdown) "$source/doc/parameters.md" || { echo "doc/parameters.md is out of date"; exit 1; }
# the paper preset reads and differs from RV-1 exactly where D2 says
"$servodrift" params "$source/examples/paper.prm" > /dev/null
echo ok
