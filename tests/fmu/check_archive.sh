#!/usr/bin/env bash
# The archive as FMI 2.0 asks: modelDescription.xml valid against the standard's XSD (xmllint), the
# binary exporting only fmi2* functions (nm -D) and needing nothing but the C library at run time
# (no deal.II, VTK, gmsh, MPI, OpenTURNS, SUNDIALS or C++ runtime of the build machine).
set -euo pipefail
fmu=$1 schema=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
python3 -c "import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall('.')" "$fmu"
for f in modelDescription.xml binaries/linux64/servodrift_valve.so resources/parameters.prm \
         resources/provenance.txt resources/tables/torque_motor.csv resources/tables/spring_tube.csv \
         resources/tables/fixed_orifice.csv resources/tables/nozzle_flapper.csv documentation/index.html; do
  test -s "$f" || { echo "missing in the archive: $f"; exit 1; }
done
xmllint --noout --schema "$schema/fmi2ModelDescription.xsd" modelDescription.xml
others=$(nm -D --defined-only binaries/linux64/servodrift_valve.so | awk '{print $3}' | grep -v '^fmi2' || true)
[ -z "$others" ] || { echo "exported beyond fmi2*: $others"; exit 1; }
count=$(nm -D --defined-only binaries/linux64/servodrift_valve.so | grep -c ' fmi2')
needed=$(readelf -d binaries/linux64/servodrift_valve.so | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
for lib in $needed; do
  case $lib in
    libc.so.*|libm.so.*|ld-linux*) ;;
    *) echo "the binary needs $lib at run time"; exit 1 ;;
  esac
done
echo "modelDescription.xml valid; $count fmi2* functions exported, nothing else; needs only: $needed"
