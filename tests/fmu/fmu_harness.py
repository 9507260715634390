#!/usr/bin/env python3
"""An FMI 2.0 host that is not servodrift's code path: Python's ctypes loads the FMU's binary, scipy's
BDF integrator drives Model Exchange, fmi2DoStep drives Co-Simulation. Each check compares the FMU
with what `servodrift dynamics' or the static drift map wrote for the same valve and exits non-zero on
a failure, printing what it measured.

  fmu_harness.py FMU RUN_DIR step        step 0 -> rated current at each temperature of the step
                                         response, ME and CS, against system/step_response.csv
  fmu_harness.py FMU RUN_DIR ramp        a slow oil-temperature ramp with a slow null-holding loop on
                                         the current, against system/drift_map.csv's null shift
  fmu_harness.py FMU RUN_DIR instances   two instances at two temperatures in one process
  fmu_harness.py FMU RUN_DIR errors      bad calls and bad resources: fmi2Error and a message, no crash
  fmu_harness.py FMU RUN_DIR resources   a table replaced in resources/ changes the model
  fmu_harness.py FMU RUN_DIR static      both drives start at a static operating point
  fmu_harness.py FMU RUN_DIR port        the external brake port
"""
import ctypes
import csv
import os
import shutil
import sys
import tempfile
import time
import zipfile
import xml.etree.ElementTree as ET

import numpy as np
from scipy.integrate import solve_ivp

fmi2OK, fmi2Warning, fmi2Discard, fmi2Error = 0, 1, 2, 3
LOGGER = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p,
                          ctypes.c_char_p, ctypes.c_char_p)  # the message is "%s" and its one argument
ALLOCATE = ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.c_size_t, ctypes.c_size_t)
FREE = ctypes.CFUNCTYPE(None, ctypes.c_void_p)
STEP_FINISHED = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int)


class Callbacks(ctypes.Structure):
    _fields_ = [("logger", LOGGER), ("allocateMemory", ALLOCATE), ("freeMemory", FREE),
                ("stepFinished", STEP_FINISHED), ("componentEnvironment", ctypes.c_void_p)]


libc = ctypes.CDLL(None)
libc.calloc.restype = ctypes.c_void_p
libc.calloc.argtypes = [ctypes.c_size_t, ctypes.c_size_t]
libc.free.argtypes = [ctypes.c_void_p]


class Fmu:
    """The unpacked archive: its model description and its binary."""

    def __init__(self, path, directory=None):
        self.directory = directory or tempfile.mkdtemp(prefix="fmu-harness-")
        with zipfile.ZipFile(path) as z:
            z.extractall(self.directory)
        root = ET.parse(os.path.join(self.directory, "modelDescription.xml")).getroot()
        self.guid = root.get("guid")
        self.vr, self.start, self.states = {}, {}, []
        for v in root.find("ModelVariables"):
            name = v.get("name")
            self.vr[name] = int(v.get("valueReference"))
            child = v[0]
            if child.get("start") is not None:
                self.start[name] = child.get("start")
            if name.startswith("der("):
                self.states.append(name[4:-1])
        self.dll = ctypes.CDLL(os.path.join(self.directory, "binaries", "linux64", "servodrift_valve.so"))
        d = self.dll
        d.fmi2Instantiate.restype = ctypes.c_void_p
        d.fmi2Instantiate.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p,
                                      ctypes.POINTER(Callbacks), ctypes.c_int, ctypes.c_int]
        d.fmi2FreeInstance.argtypes = [ctypes.c_void_p]
        for f in ("fmi2GetReal", "fmi2SetReal"):
            getattr(d, f).argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_uint), ctypes.c_size_t,
                                      ctypes.POINTER(ctypes.c_double)]
        for f in ("fmi2GetBoolean", "fmi2SetBoolean"):
            getattr(d, f).argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_uint), ctypes.c_size_t,
                                      ctypes.POINTER(ctypes.c_int)]
        for f in ("fmi2GetContinuousStates", "fmi2SetContinuousStates", "fmi2GetDerivatives",
                  "fmi2GetNominalsOfContinuousStates"):
            getattr(d, f).argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t]
        d.fmi2SetupExperiment.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_double, ctypes.c_double,
                                          ctypes.c_int, ctypes.c_double]
        d.fmi2DoStep.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_int]
        d.fmi2SetTime.argtypes = [ctypes.c_void_p, ctypes.c_double]
        for f in ("fmi2EnterInitializationMode", "fmi2ExitInitializationMode", "fmi2EnterContinuousTimeMode",
                  "fmi2Terminate", "fmi2Reset"):
            getattr(d, f).argtypes = [ctypes.c_void_p]
        d.fmi2GetFMUstate.argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p)]
        d.fmi2SetFMUstate.argtypes = [ctypes.c_void_p, ctypes.c_void_p]
        d.fmi2FreeFMUstate.argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p)]
        d.fmi2GetVersion.restype = ctypes.c_char_p
        d.fmi2GetTypesPlatform.restype = ctypes.c_char_p

    def resources_uri(self):
        return "file://" + os.path.join(self.directory, "resources")


class Instance:
    def __init__(self, fmu, kind, name="valve", guid=None, resources=None):
        self.fmu, self.messages = fmu, []
        self._logger = LOGGER(lambda env, inst, status, cat, fmt, arg: self.messages.append(
            (status, (arg or b"").decode())))
        self._callbacks = Callbacks(self._logger, ALLOCATE(libc.calloc), FREE(libc.free), STEP_FINISHED(), None)
        self.c = fmu.dll.fmi2Instantiate(name.encode(), kind, (guid or fmu.guid).encode(),
                                         (resources or fmu.resources_uri()).encode(),
                                         ctypes.byref(self._callbacks), 0, 0)
        self.n = len(fmu.states)

    def check(self, status, what):
        if status not in (fmi2OK, fmi2Warning):
            raise RuntimeError(f"{what}: status {status}: {self.messages[-1:]}")

    def set(self, **values):
        vr = (ctypes.c_uint * len(values))(*[self.fmu.vr[k] for k in values])
        v = (ctypes.c_double * len(values))(*values.values())
        self.check(self.fmu.dll.fmi2SetReal(self.c, vr, len(values), v), "fmi2SetReal")

    def get(self, *names):
        vr = (ctypes.c_uint * len(names))(*[self.fmu.vr[k] for k in names])
        v = (ctypes.c_double * len(names))()
        self.check(self.fmu.dll.fmi2GetReal(self.c, vr, len(names), v), "fmi2GetReal")
        return list(v)

    def initialize(self, **inputs):
        d = self.fmu.dll
        self.check(d.fmi2SetupExperiment(self.c, 0, 0.0, 0.0, 0, 0.0), "fmi2SetupExperiment")
        self.check(d.fmi2EnterInitializationMode(self.c), "fmi2EnterInitializationMode")
        if inputs:
            self.set(**inputs)
        self.check(d.fmi2ExitInitializationMode(self.c), "fmi2ExitInitializationMode")

    def vector(self, function):
        x = (ctypes.c_double * self.n)()
        self.check(function(self.c, x, self.n), function.__name__)
        return np.array(x)

    def states(self):
        return self.vector(self.fmu.dll.fmi2GetContinuousStates)

    def nominals(self):
        return self.vector(self.fmu.dll.fmi2GetNominalsOfContinuousStates)

    def derivatives(self, t, x):
        d = self.fmu.dll
        self.check(d.fmi2SetTime(self.c, t), "fmi2SetTime")
        self.check(d.fmi2SetContinuousStates(self.c, (ctypes.c_double * self.n)(*x), self.n),
                   "fmi2SetContinuousStates")
        return self.vector(d.fmi2GetDerivatives)

    def do_step(self, t, h):
        self.check(self.fmu.dll.fmi2DoStep(self.c, t, h, 1), "fmi2DoStep")

    def free(self):
        self.fmu.dll.fmi2FreeInstance(self.c)


KELVIN = 273.15
ME, CS = 0, 1


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def step_reference(run_dir):
    """The large steps of system/step_response.csv by temperature: times, p_B, x_v, x_f and the command."""
    steps = {}
    for r in read_csv(os.path.join(run_dir, "system", "step_response.csv")):
        if r["step[-]"] != "large":
            continue
        s = steps.setdefault(float(r["temperature[degC]"]), {k: [] for k in ("t", "p_B", "x_v", "x_f", "i")})
        s["t"].append(float(r["time[s]"]))
        s["p_B"].append(float(r["brake_pressure[Pa]"]))
        s["x_v"].append(float(r["spool_displacement[m]"]))
        s["x_f"].append(float(r["flapper_displacement[m]"]))
        s["i"].append(float(r["command_current[A]"]))
    return {T: {k: np.array(v) for k, v in s.items()} for T, s in steps.items()}


OUTPUTS = (("p_B", "brake_pressure"), ("x_v", "spool_position"), ("x_f", "flapper_position"))


def outputs_at_states(instance, t, x):
    instance.derivatives(t, x)  # sets time and states
    return instance.get(*[o for _, o in OUTPUTS])


def dynamics_tolerances(fmu):
    """Dynamics/Relative tolerance and Absolute tolerance of resources/parameters.prm: the reference's
    CVODE and the FMU's Co-Simulation ran with them"""
    values, section = {}, []
    for line in open(os.path.join(fmu.directory, "resources", "parameters.prm")):
        line = line.split("#")[0].strip()
        if line.startswith("subsection "):
            section.append(line[11:].strip())
        elif line == "end":
            section.pop()
        elif line.startswith("set ") and section == ["Dynamics"]:
            key, value = line[4:].split("=", 1)
            values[key.strip()] = value.strip()
    return float(values["Relative tolerance"]), float(values["Absolute tolerance"])


def check_step(fmu, run_dir):
    """Both kinds reproduce `servodrift dynamics' own step within a bound set by the integrators'
    tolerances: the reference's CVODE and the FMU's Co-Simulation run with the valve file's relative
    tolerance rtol (per state scale: atol), ME with scipy's BDF at 1e-9 relative. The global error of a
    variable-step BDF run over this transient (50 % overshoot, contacts) is tens of its local
    tolerances (20-40 measured between the kinds): the bound is 100 rtol of the change of each output
    plus 100 atol of its scale (ME's nominal of the state; x_f's largest value)."""
    rtol, atol = dynamics_tolerances(fmu)
    failures = 0
    for T, ref in sorted(step_reference(run_dir).items()):
        rated = ref["i"][-1]
        times = ref["t"]
        for kind in (ME, CS):
            inst = Instance(fmu, kind, f"step-{T}-{kind}")
            inst.initialize(coil_current=ref["i"][0], oil_temperature=T + KELVIN)
            inst.set(coil_current=rated)
            nominal = inst.nominals()
            scale = {"p_B": nominal[6], "x_v": nominal[4], "x_f": np.max(np.abs(ref["x_f"]))}
            got = []
            if kind == ME:
                sol = solve_ivp(lambda t, x: inst.derivatives(t, x), (0, times[-1]), inst.states(), method="BDF",
                                rtol=1e-9, atol=1e-11 * nominal, dense_output=True)
                if not sol.success:
                    raise RuntimeError(f"solve_ivp at {T} degC: {sol.message}")
                for t in times:
                    got.append(outputs_at_states(inst, t, sol.sol(t)))
            else:
                got.append(inst.get(*[o for _, o in OUTPUTS]))
                for k in range(1, len(times)):
                    inst.do_step(times[k - 1], times[k] - times[k - 1])
                    got.append(inst.get(*[o for _, o in OUTPUTS]))
            got = np.array(got)
            for j, (key, name) in enumerate(OUTPUTS):
                change = abs(ref[key][-1] - ref[key][0])
                err = np.max(np.abs(got[:, j] - ref[key]))
                bound = 100 * (rtol * change + atol * scale[key])
                ok = err <= bound
                failures += not ok
                print(f"{'ME' if kind == ME else 'CS'} {T:6.1f} degC {name:17s} max |FMU - dynamics| = {err:.3e}"
                      f" (change {change:.3e}, bound {bound:.3e}) {'ok' if ok else 'FAILED'}")
            inst.free()
    return failures


def drift_reference(run_dir, deviation):
    """null_shift_current[A] of system/drift_map.csv at a deviation angle [deg], by temperature"""
    return {float(r["temperature[degC]"]): float(r["null_shift_current[A]"])
            for r in read_csv(os.path.join(run_dir, "system", "drift_map.csv"))
            if abs(float(r["deviation_angle[deg]"]) - deviation) < 1e-12 and r["null_shift_current[A]"]}


def check_ramp(fmu, run_dir):
    """A slow oil-temperature ramp over the tables' range (Co-Simulation, communication steps of H s,
    the temperature and the current updated at each) with a slow integral loop on the current that
    holds the pilot stage at null (p_L = p_R): the current it needs is the drift map's null-shift
    current at every temperature (the valve with a magnetic null of DEVIATION deg, nulled at the
    reference temperature: the FMU's parameter). The loop's time constant tau (well above the
    spool's travel, which consumes control flow while p_L != p_R) lags the current by tau di/dt;
    the bound is three times that lag plus 1e-3 of the largest null shift (the loop's Euler steps
    and the integrators' tolerances)."""
    deviation = 0.05
    reference = drift_reference(run_dir, deviation)
    T_low, T_high = min(reference), max(reference)

    def started(current):
        inst = Instance(fmu, CS, f"ramp-{current}")
        d = fmu.dll
        inst.check(d.fmi2EnterInitializationMode(inst.c), "fmi2EnterInitializationMode")
        inst.set(magnetic_null=np.radians(deviation), coil_current=current, oil_temperature=T_low + KELVIN)
        inst.check(d.fmi2ExitInitializationMode(inst.c), "fmi2ExitInitializationMode")
        return inst

    def pressure_difference(inst):
        p_L, p_R = inst.get("left_control_pressure", "right_control_pressure")
        return p_L - p_R

    # the loop's gain from the static pressure gain d(p_L - p_R)/di at the start
    probe = 1e-5
    plus, minus = started(probe), started(-probe)
    gain = (pressure_difference(plus) - pressure_difference(minus)) / (2 * probe)
    plus.free(), minus.free()
    tau, settle, ramp, H = 0.2, 1.0, 20.0, 0.005
    end = 2 * settle + ramp
    inst = started(0.0)
    current, t, samples = 0.0, 0.0, []
    for k in range(int(round(end / H))):
        T = T_low + (T_high - T_low) * min(max(t - settle, 0.0) / ramp, 1.0)
        inst.set(coil_current=current, oil_temperature=T + KELVIN)
        inst.do_step(t, H)
        t += H
        current -= H * pressure_difference(inst) / (gain * tau)
        samples.append((t, current))
    inst.free()
    times, currents = np.array(samples).T
    slope = abs(reference[T_high] - reference[T_low]) / ramp
    bound = 3 * tau * slope + 1e-3 * max(abs(v) for v in reference.values())
    failures = 0
    for T in sorted(reference):
        t = end if T == T_high else settle + ramp * (T - T_low) / (T_high - T_low)
        got = np.interp(t, times, currents)
        ok = abs(got - reference[T]) <= bound
        failures += not ok
        print(f"{T:6.1f} degC null-shift current: FMU loop {got:.6e} A, drift map {reference[T]:.6e} A,"
              f" |diff| {abs(got - reference[T]):.2e} (bound {bound:.2e}) {'ok' if ok else 'FAILED'}")
    return failures


def static_reference(run_dir):
    """final[SI] of the large steps' brake pressure in system/step_metrics.csv (the static point at
    the rated current), by temperature"""
    return {float(r["temperature[degC]"]): float(r["final[SI]"])
            for r in read_csv(os.path.join(run_dir, "system", "step_metrics.csv"))
            if r["step[-]"] == "large" and r["output[-]"] == "brake_pressure"}


def check_instances(fmu, run_dir):
    """Two instances at the lowest and highest temperature in one process, called in turn, each give
    their own static brake pressure at the rated current: the static model's (step_metrics.csv), to
    1e-9 relative (the same equations, solved by the same static model); and the first gives the same
    value before and after the second exists (no global state)."""
    reference = static_reference(run_dir)
    rated = step_reference(run_dir)[min(reference)]["i"][-1]
    failures = 0
    a = Instance(fmu, ME, "cold")
    a.initialize(coil_current=rated, oil_temperature=min(reference) + KELVIN)
    first = a.get("brake_pressure")[0]
    b = Instance(fmu, ME, "hot")
    b.initialize(coil_current=rated, oil_temperature=max(reference) + KELVIN)
    for name, inst, T, value in (("a", a, min(reference), None), ("b", b, max(reference), None),
                                 ("a again", a, min(reference), first)):
        got = inst.get("brake_pressure")[0]
        ok = abs(got - reference[T]) <= 1e-9 * abs(reference[T]) and (value is None or got == value)
        failures += not ok
        print(f"instance {name} at {T} degC: p_B = {got:.10e} Pa, static model {reference[T]:.10e} Pa"
              f" {'ok' if ok else 'FAILED'}")
    a.free(), b.free()
    return failures


def check_errors(fmu, run_dir):
    """What a host or a damaged archive can do wrong gives fmi2Error (or NULL from fmi2Instantiate)
    and one logged message that says what, never a crash; a temperature beyond the tables warns and
    holds the end value; an FMU state set back repeats a step exactly."""
    failures = 0

    def expect(ok, what, detail=""):
        nonlocal failures
        failures += not ok
        print(f"{what}: {'ok' if ok else 'FAILED'} {detail}")

    def refused_instance(what, needle, **kwargs):
        inst = Instance(fmu, ME, what, **kwargs)
        text = " ".join(m for _, m in inst.messages)
        expect(not inst.c and needle in text, what, text[:160])

    refused_instance("wrong GUID", "GUID", guid="{00000000-0000-0000-0000-000000000000}")
    refused_instance("no resources", "cannot be read", resources="file:///nonexistent/resources")
    damaged = tempfile.mkdtemp(prefix="fmu-damaged-")
    try:
        for table, damage, needle in (("spring_tube.csv", None, "spring_tube"),
                                      ("torque_motor.csv", "truncate", "torque_motor")):
            shutil.rmtree(damaged)
            shutil.copytree(os.path.join(fmu.directory, "resources"), damaged)
            path = os.path.join(damaged, "tables", table)
            if damage is None:
                os.remove(path)
            else:
                with open(path, "r+") as f:
                    text = f.read()
                    f.seek(0), f.truncate(), f.write(text[: len(text) // 2] + "\n1,2,x\n")
            refused_instance(f"{table} {'missing' if damage is None else 'damaged'}", needle,
                             resources="file://" + damaged)
    finally:
        shutil.rmtree(damaged, ignore_errors=True)

    inst = Instance(fmu, CS, "errors")
    inst.initialize()
    d = fmu.dll
    status = d.fmi2SetReal(inst.c, (ctypes.c_uint * 1)(fmu.vr["coil_current"]), 1, (ctypes.c_double * 1)(float("nan")))
    expect(status == fmi2Error and "not a finite number" in inst.messages[-1][1], "NaN input", inst.messages[-1][1])
    status = d.fmi2SetReal(inst.c, (ctypes.c_uint * 1)(fmu.vr["magnetic_null"]), 1, (ctypes.c_double * 1)(0.001))
    expect(status == fmi2Error and "fixed after initialisation" in inst.messages[-1][1], "parameter after start",
           inst.messages[-1][1])
    status = d.fmi2GetReal(inst.c, (ctypes.c_uint * 1)(10 ** 6), 1, (ctypes.c_double * 1)())
    expect(status == fmi2Error and "value reference" in inst.messages[-1][1], "unknown value reference",
           inst.messages[-1][1])
    # beyond the tables: a warning, and the valve held at the end value
    high = float(fmu.start["oil_temperature"])
    root = ET.parse(os.path.join(fmu.directory, "modelDescription.xml")).getroot()
    T_max = [float(v[0].get("max")) for v in root.find("ModelVariables") if v.get("name") == "oil_temperature"][0]
    inst.set(oil_temperature=T_max)
    at_end = inst.get("der(left_control_pressure_state)")[0]
    vr = (ctypes.c_uint * 1)(fmu.vr["oil_temperature"])
    status = d.fmi2SetReal(inst.c, vr, 1, (ctypes.c_double * 1)(T_max + 15))
    beyond = inst.get("der(left_control_pressure_state)", "beyond_tables")
    expect(status in (fmi2OK, fmi2Warning) and beyond[0] == at_end and beyond[1] == 1 and
           any(s == fmi2Warning and "held at the end value" in m for s, m in inst.messages),
           "temperature beyond the tables", inst.messages[-1][1])
    inst.set(oil_temperature=high)
    # an FMU state set back repeats the steps exactly
    inst.set(coil_current=float(fmu.start.get("coil_current", 0)) + 0.01)
    inst.do_step(0.0, 0.001)
    state = ctypes.c_void_p()
    inst.check(d.fmi2GetFMUstate(inst.c, ctypes.byref(state)), "fmi2GetFMUstate")
    inst.do_step(0.001, 0.002)
    first = inst.get("brake_pressure", "spool_position")
    inst.check(d.fmi2SetFMUstate(inst.c, state), "fmi2SetFMUstate")
    inst.do_step(0.001, 0.002)
    again = inst.get("brake_pressure", "spool_position")
    inst.check(d.fmi2FreeFMUstate(inst.c, ctypes.byref(state)), "fmi2FreeFMUstate")
    expect(first == again, "FMU state set back", f"{first} {again}")
    status = d.fmi2DoStep(inst.c, 0.003, -1.0, 1)
    expect(status == fmi2Error, "negative step", inst.messages[-1][1])
    inst.free()
    me = Instance(fmu, ME, "me")
    me.initialize()
    status = d.fmi2DoStep(me.c, 0.0, 0.001, 1)
    expect(status == fmi2Error and "Model Exchange cannot step" in me.messages[-1][1], "fmi2DoStep on Model Exchange",
           me.messages[-1][1])
    me.free()
    return failures


def check_resources(fmu, run_dir):
    """Replacing a table in resources/ changes the model: with the spring tube 5 % stiffer the static
    armature angle at the rated current falls to at most 1/1.05 of itself (E29: theta ~ T_em/(K_a -
    K_m + ...), where the magnetic spring K_m makes the net stiffness rise by more than 5 %)."""
    rated = step_reference(run_dir)[min(static_reference(run_dir))]["i"][-1]

    def angle(resources):
        inst = Instance(fmu, ME, "resources", resources=resources)
        inst.initialize(coil_current=rated)
        value = inst.get("armature_angle")[0]
        inst.free()
        return value

    original = angle(None)
    stiffer = tempfile.mkdtemp(prefix="fmu-stiffer-")
    try:
        shutil.rmtree(stiffer)
        shutil.copytree(os.path.join(fmu.directory, "resources"), stiffer)
        path = os.path.join(stiffer, "tables", "spring_tube.csv")
        lines = open(path).read().splitlines()
        header = next(k for k, line in enumerate(lines) if not line.startswith("#"))
        column = lines[header].split(",").index("stiffness[N*m/rad]")
        for k in range(header + 1, len(lines)):
            cells = lines[k].split(",")
            cells[column] = repr(1.05 * float(cells[column]))
            lines[k] = ",".join(cells)
        open(path, "w").write("\n".join(lines) + "\n")
        changed = angle("file://" + stiffer)
    finally:
        shutil.rmtree(stiffer, ignore_errors=True)
    ok = 0.8 < changed / original <= 1 / 1.05
    print(f"armature angle at the rated current: {original:.6e} rad, with the spring tube 5 % stiffer "
          f"{changed:.6e} rad (ratio {changed / original:.4f}, at most 1/1.05 expected) {'ok' if ok else 'FAILED'}")
    return 0 if ok else 1


def check_static(fmu, run_dir):
    """Both drives start at a static operating point: at initialisation, for inputs across the
    torque table's currents (current drive) or up to 3 V (voltage drive, the valve of
    RUN_DIR/voltage/servodrift_valve.fmu, 8 states), at the tables' lowest and highest temperature,
    every derivative of Model Exchange is below 1e-9 of its state's scale per 0.1 ms (the valve's
    fastest time constants are of that order: the tolerance of the static point's own check in
    tests/verification/dynamics_test.cc, 1e-9 of the scale times sqrt(K_a/J_a))."""
    failures = 0
    root = ET.parse(os.path.join(fmu.directory, "modelDescription.xml")).getroot()
    temperature = [v[0] for v in root.find("ModelVariables") if v.get("name") == "oil_temperature"][0]
    for drive, path in (("current", None), ("voltage", os.path.join(run_dir, "voltage", "servodrift_valve.fmu"))):
        f = fmu if path is None else Fmu(path)
        try:
            signal = "coil_current" if drive == "current" else "coil_voltage"
            values = [-0.02, -0.005, 0.0, 0.01, 0.02] if drive == "current" else [-3.0, 0.0, 1.5, 3.0]
            expected_states = 7 if drive == "current" else 8
            if len(f.states) != expected_states or signal not in f.vr:
                failures += 1
                print(f"{drive} drive: {len(f.states)} states and no `{signal}' input: FAILED")
                continue
            worst = 0.0
            for T in (float(temperature.get("min")), float(temperature.get("max"))):
                for value in values:
                    inst = Instance(f, ME, "static")
                    inst.initialize(**{signal: value, "oil_temperature": T})
                    x = inst.states()
                    rates = inst.derivatives(0.0, x)
                    worst = max(worst, float(np.max(np.abs(rates) * 1e-4 / inst.nominals())))
                    inst.free()
            ok = worst <= 1e-9
            failures += not ok
            print(f"{drive} drive, {len(f.states)} states: largest |rate| x 0.1 ms / scale at the start = {worst:.2e}"
                  f" (bound 1e-9) {'ok' if ok else 'FAILED'}")
        finally:
            if path is not None:
                shutil.rmtree(f.directory, ignore_errors=True)
    return failures


def check_port(fmu, run_dir):
    """The external brake port (parameter external_brake_port): with the port held at the static brake
    pressure of the valve's own volume, the valve is static there as well and no flow crosses the
    port (E36/E37: the blocked volume's pressure is where the metering edges' flows balance); 1 MPa
    above it, oil flows back out of the port (brake_flow < 0), the brake pressure is the port's and its
    state does not move. Bounds: every rate 1e-9 of its scale per 0.1 ms (as fmu.static); the flow
    1e-9 of the supply edge's flow at null."""
    rated = step_reference(run_dir)[min(static_reference(run_dir))]["i"][-1]
    failures = 0
    for current in (0.0, 0.5 * rated, rated):
        own = Instance(fmu, ME, "own")
        own.initialize(coil_current=current)
        p_B, supply = own.get("brake_pressure", "supply_flow")
        own.free()
        port = Instance(fmu, ME, "port")
        d = fmu.dll
        port.check(d.fmi2EnterInitializationMode(port.c), "fmi2EnterInitializationMode")
        port.check(d.fmi2SetBoolean(port.c, (ctypes.c_uint * 1)(fmu.vr["external_brake_port"]), 1,
                                    (ctypes.c_int * 1)(1)), "fmi2SetBoolean")
        port.set(coil_current=current, brake_port_pressure=p_B)
        port.check(d.fmi2ExitInitializationMode(port.c), "fmi2ExitInitializationMode")
        x = port.states()
        rates = port.derivatives(0.0, x)
        worst = float(np.max(np.abs(rates) * 1e-4 / port.nominals()))
        flow = port.get("brake_flow")[0]
        port.set(brake_port_pressure=p_B + 1e6)
        rates_up = port.derivatives(0.0, x)
        flow_up, p_out = port.get("brake_flow", "brake_pressure")
        port.free()
        ok = (worst <= 1e-9 and abs(flow) <= 1e-9 * max(abs(supply), 1e-12) and flow_up < 0 and
              p_out == p_B + 1e6 and rates_up[6] == 0)
        failures += not ok
        print(f"i = {current:.4f} A: port at p_B = {p_B:.6e} Pa: largest rate {worst:.1e}, brake_flow {flow:.2e} m3/s;"
              f" 1 MPa above: brake_flow {flow_up:.3e} m3/s, brake_pressure {p_out:.6e} Pa {'ok' if ok else 'FAILED'}")
    return failures


def main():
    fmu_path, run_dir, what = sys.argv[1:4]
    fmu = Fmu(fmu_path)
    try:
        failures = {"step": check_step, "ramp": check_ramp, "instances": check_instances,
                    "errors": check_errors, "resources": check_resources,
                    "static": check_static, "port": check_port}[what](fmu, run_dir)
    finally:
        shutil.rmtree(fmu.directory, ignore_errors=True)
    print(f"{what}: {'FAILED ' + str(failures) + ' checks' if failures else 'all checks passed'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
