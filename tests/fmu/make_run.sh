#!/usr/bin/env bash
# The run the FMU checks compare with: RV-1 at the reduced order on three temperatures (tables over
# the paper's 40-120 degC, where the voltage-driven coil's current stays within the torque table),
# exported as an FMU (`servodrift export-fmu --reduced-order') and analysed by `servodrift dynamics'
# from the same tables,
# both integrating with CVODE at 1e-9 relative (the step check compares the two at their tolerances);
# the tables also as MAT and Modelica text (check_tables.py); and the same valve under voltage drive.
set -euo pipefail
sd=$1 dir=$2
rm -rf "$dir"
set_levels=(--set "Torque motor/Model level=reduced-order" --set "Spring tube/Model level=reduced-order"
            --set "Pilot stage/Model level=reduced-order" --set "Sweeps/Table temperatures=40, 50, 60, 70, 80, 90, 100, 110, 120"
            --set "Sweeps/Drift temperatures=40, 80, 120"
            --set "Sweeps/Deviation angles=0, 0.05" --set "Dynamics/Sine frequencies=100"
            --set "Dynamics/Sine amplitudes=0.1" --set "Dynamics/Large-signal temperatures=1"
            --set "Dynamics/Relative tolerance=1e-9" --set "Dynamics/Absolute tolerance=1e-11"
            --set "Output/Plots=false" --set "Output/Formats=csv, mat, modelica")
"$sd" export-fmu --reduced-order -o "$dir" "${set_levels[@]}" > /dev/null
"$sd" dynamics -o "$dir" "${set_levels[@]}" > /dev/null
"$sd" export-fmu --reduced-order -o "$dir/voltage" "${set_levels[@]}" --set "Torque motor/Coil drive=voltage" > /dev/null
test -s "$dir/servodrift_valve.fmu" && test -s "$dir/system/step_response.csv" && test -s "$dir/system/drift_map.csv"
test -s "$dir/tables/servodrift_tables.mat" && test -s "$dir/tables/servodrift_tables.txt"
