#!/usr/bin/env python3
"""The tables for system tools without FMI (Output/Formats = csv, mat, modelica): tables/servodrift_tables.mat
read by scipy.io.loadmat and tables/servodrift_tables.txt read as Modelica text tables hold every value of
the CSV tables exactly (the same doubles: the writer reads the CSV files) and the drift map of
system/drift_map.csv within the CSV's 12 printed digits (relative 1e-11; the deviation angle in rad).

  check_tables.py RUN_DIR
"""
import csv
import math
import os
import sys

import numpy as np
import scipy.io as sio


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    return rows[0], rows[1:]


def read_modelica(path):
    """{name: matrix} of a Modelica text table file (`#1', `double name(rows, cols)', rows of numbers)"""
    tables, lines = {}, [line.split("#")[0].strip() for line in open(path)]
    assert open(path).readline().strip() == "#1", "no #1 header"
    k = 0
    while k < len(lines):
        line = lines[k]
        k += 1
        if line.startswith("double "):
            name, size = line[7:].split("(")
            rows, cols = (int(v) for v in size.rstrip(")").split(","))
            matrix = []
            while len(matrix) < rows:
                if lines[k]:
                    matrix.append([float(v) for v in lines[k].split()])
                    assert len(matrix[-1]) == cols, f"{name}: a row of {len(matrix[-1])} numbers, {cols} declared"
                k += 1
            tables[name] = np.array(matrix)
    return tables


def main():
    run_dir = sys.argv[1]
    mat = sio.loadmat(os.path.join(run_dir, "tables", "servodrift_tables.mat"))
    modelica = read_modelica(os.path.join(run_dir, "tables", "servodrift_tables.txt"))
    failures, checked = 0, 0
    axes_of = {"torque_motor": 3, "spring_tube": 1, "fixed_orifice": 2, "nozzle_flapper": 3}
    for name, n_axes in axes_of.items():
        header, rows = read_csv(os.path.join(run_dir, "tables", name + ".csv"))
        names = [h.split("[")[0] for h in header]
        s = mat[name]
        axes = [s[n][0, 0].ravel() for n in names[:n_axes]]
        for row in rows:
            values = [float(v) for v in row]
            index = tuple(int(np.where(axes[a] == values[a])[0][0]) for a in range(n_axes))
            for c in range(n_axes, len(names)):
                q = s[names[c]][0, 0]
                got = q[index] if n_axes > 1 else q.ravel()[index[0]]
                # Modelica: 1 axis: [axis, quantities]; 2: rows axis 0, columns axis 1; 3: per axis-0 value
                if n_axes == 1:
                    text = modelica[name][index[0], c]
                elif n_axes == 2:
                    text = modelica[f"{name}_{names[c]}"][index[0] + 1, index[1] + 1]
                else:
                    text = modelica[f"{name}_{names[c]}_{index[0] + 1}"][index[1] + 1, index[2] + 1]
                checked += 1
                if got != values[c] or text != values[c]:
                    failures += 1
                    print(f"{name} {names[c]} at {values[:n_axes]}: CSV {values[c]!r}, MAT {got!r}, Modelica {text!r}")
    header, rows = read_csv(os.path.join(run_dir, "system", "drift_map.csv"))
    d = mat["drift_map"]
    T, angle = d["temperature"][0, 0].ravel(), d["deviation_angle"][0, 0].ravel()
    for row in rows:
        r = dict(zip(header, row))
        i = int(np.argmin(abs(T - float(r["temperature[degC]"]))))
        j = int(np.argmin(abs(angle - math.radians(float(r["deviation_angle[deg]"])))))
        for q, column in (("brake_pressure", "brake_pressure[Pa]"), ("null_shift_current", "null_shift_current[A]"),
                          ("spool_displacement", "spool_displacement[m]")):
            if not r[column]:
                continue
            expected = float(r[column])
            for got in (d[q][0, 0][i, j], modelica[f"drift_map_{q}"][i + 1, j + 1]):
                checked += 1
                if abs(got - expected) > 1e-11 * max(abs(expected), 1e-30) and abs(got - expected) > 1e-20:
                    failures += 1
                    print(f"drift map {q} at {r['temperature[degC]']} degC, {r['deviation_angle[deg]']} deg: "
                          f"CSV {expected!r}, got {got!r}")
    print(f"{checked} values of the tables and the drift map compared: "
          f"{'all equal' if not failures else str(failures) + ' differ'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
