"""The benchmark drive of ``benchmarks/simulate.py`` in Exudyn (the second peer).

Exudyn (J. Gerstmayr, University of Innsbruck; https://github.com/jgerstmayr/EXUDYN, on
the package index as ``exudyn``) is a flexible multibody engine with a C++ core. Its own
chain-drive example, ``main/pythonDev/Examples/chainDriveExample.py`` (Gerstmayr,
2024-11-01), models a roller chain as 2-D rigid bodies joined by ``RevoluteJoint2D`` and
the sprockets' contact with the rollers by ``ObjectContactCurveCircles`` (a sprocket
outline of straight segments carried by the wheel's marker, the rollers as circles),
solved by the implicit generalized-α integrator with a sparse solver and modified Newton
(``EigenSparse``, ``useModifiedNewton``). This peer follows it, with the drive of
``benchmarks/simulate.py`` (the same model and assembled state as the MuJoCo peer):

* each roller a ``NodeRigidBody2D`` / ``ObjectRigidBody2D`` (the link mass at the pin;
  the circle marker needs an orientation, the rotation is free and carries no torque:
  Exudyn's curve contact applies its forces at the circle centre);
* **stiff links** (``rigid=False``): ``ObjectConnectorSpringDamper`` between consecutive
  rollers with chaindrive's ``k = EA/p``, ``c`` and rest length ``p``;
  **rigid links** (``rigid=True``): ``ObjectConnectorDistance`` (a distance constraint,
  the length of the assembled state), the tension read from its Lagrange multiplier;
* teeth: chaindrive's working profile (ISO 606 seat arc ``r_s``, ``±ψ_s``, and the convex
  flank arcs ``r_e`` up to the tooth corner; ``chaindrive.simulation.model.iso_flank``) as
  straight segments: ``SEAT_FACES`` faces tangent to each seat arc (the roller centre's
  free region differs from the circular one by ``(r_s − r)(1/cos(Δ/2) − 1)`` < 1 µm) and
  joined to the flanks' ends by two short segments, ``FLANK_FACES`` chords of each flank
  arc (sagitta ``r_e(1 − cos(Δ/2))``), the tips as chords;
* contact: ``ObjectContactCurveCircles`` with ``contactModel = 0``, whose normal force is
  ``l_seg (k_c δ + d_c δ̇)`` per touching segment (measured: the force of one segment
  is proportional to its length ``l_seg``), so every class of equally long segments (seat
  faces, flank faces, tip chords) is one contact object with ``k_c = k / l_seg`` and
  ``d_c = c / l_seg`` (chaindrive's contact stiffness ``k`` and damping ``c`` per roller);
  regularised Coulomb friction ``μ = 0.1``, linear below ``frictionProportionalZone``
  (``CONFIG``: 0.02 m/s; chaindrive's own regularisation velocity grows with the normal
  force, ``v_e = max(μ f_n Δt_ref/m, 1 mm/s)``, 5–10 mm/s for the seated rollers'
  0.6–1.1 kN, T·2 sin(π/z); measured on this drive, mean tension against the reference: zone 1 mm/s
  +1.56 %, 5 mm/s +1.31 %, 20 mm/s +1.22 %); the rollers each wheel's contact checks
  limited to those that can reach it in the run (:func:`near_rollers`, 37 and 36 of 100
  for 0.3 s: a broad phase by hand, checked against chaindrive's run; 2.5 times faster);
* wheels: ``ObjectRigidBody2D`` pinned by ``CoordinateConstraint`` (x, y) with the same
  inertias; the driver's prescribed speed ramp by a stiff angle servo
  (``ObjectConnectorCoordinateSpringDamperExt``: offset and velocity offset the ramp's
  angle and speed, set before each step),
  the driven wheel's load torque a ``Torque`` load; gravity on every roller.

Integrator (measured on this drive, Exudyn 1.13.6): the implicit generalized-α of the
chain example does not get through the first step once friction is on (its Newton
iteration cycles between two residuals, ~1e3 N, the contacts' stick/slip switching;
without friction it converges, 2-3 discontinuous iterations of 4-7 Newton steps a step);
the explicit Euler of Exudyn (forward, not symplectic) blows up within 0.1 ms at 2 µs;
``VelocityVerlet`` (and ``RK44``) runs at chaindrive's stable step, so this peer uses it
(``SOLVER``) on the ladder ``LADDER``. Cost: 0.69 ms CPU a step (229 s per simulated
second at 3 µs), nearly all in the curve contact (every listed roller against every
segment of every contact object: 37 × 357 per wheel; 1.7–1.8 ms with all 100 rollers),
34 µs a step without it.

What else was tried on this drive (0.3 s, 3 µs, mean tight-side tension against the
reference): without contact damping (Exudyn's linear law lets the damping pull while the
penetration is positive; chaindrive's never pulls) +1.52 %; 9 seat and 12 flank faces
+1.49 %; at rest (driver held) Exudyn's tension is chaindrive's within 0.04 % (8 seat and 6
flank faces: −0.04 %; 9 and 12: −0.005 %), so the offset of the running drive is
dynamic, not the outline's; 4 µs diverges (the links' stable step, as chaindrive's).

Exudyn settings used (exudyn.readthedocs.io): ``ObjectContactCurveCircles``
(Items/ObjectContactCurveCircles), ``SolveDynamic`` with ``GeneralizedAlpha`` and
``spectralRadius``, ``newton.useModifiedNewton``, ``linearSolverType = EigenSparse``,
explicit ``RK44`` / ``ExplicitEuler`` with ``explicitIntegration.computeMassMatrixInversePerBody``.
"""

from __future__ import annotations

import math
import time

import numpy as np

from chaindrive.simulation import _kernel as K
from chaindrive.simulation.model import iso_flank

#: tangent-polygon faces per seating arc and per flank arc
SEAT_FACES = 8
FLANK_FACES = 6
#: Exudyn's integrator for the drive (see the module docstring: the implicit one fails)
SOLVER = "VelocityVerlet"
#: explicit step ladder [s] (the links' stable step is about 3 µs, as chaindrive's)
LADDER = (3.0e-6, 1.5e-6)
#: the configuration of the ladder (measured on this drive, module docstring): the friction's
#: regularisation velocity [m/s] and the faces per seat and per flank arc
CONFIG = {"friction_zone": 0.02, "seat_faces": SEAT_FACES, "flank_faces": FLANK_FACES}
#: the driver's angle servo: stiffness [N m/rad] and damping [N m s/rad]
SERVO_K = 1.0e7
SERVO_C = 5.0e2  # about critical on the driver's inertia: 2 sqrt(K J) = 473


def _arc_polygon(centre, radius, a0, a1, n, tangent, sign_b=1.0):
    """Vertices (gap frame) of ``n`` equal faces along the arc of ``radius`` about ``centre``
    from angle ``a0`` to ``a1``: tangent to it (``tangent``, every vertex at
    ``radius/cos(Δ/2)``) or its chords (every vertex on it); and the faces' length."""
    d = (a1 - a0) / n
    r = radius / math.cos(0.5 * d) if tangent else radius
    a = a0 + d * np.arange(n + 1)
    pts = centre + r * np.column_stack([np.cos(a), np.sin(a)])
    pts[:, 1] *= sign_b
    return pts, 2.0 * r * math.sin(0.5 * abs(d))


def tooth_segments(model, teeth, seat_faces=SEAT_FACES, flank_faces=FLANK_FACES):
    """Segments of the wheel's outline in its frame, going counter-clockwise (exterior on
    the right, Exudyn's convention): ``{length: (n, 4) array}``, one entry per class of
    equal segments (seat faces, flank faces, tip chords)."""
    rad = model.pitch / (2 * math.sin(math.pi / teeth))
    rs, rr, psi = model.seat, model.roller_radius, model.seat_angle(teeth)
    re, cea, ceb, ta, tb, dta, dtb = iso_flank(model.pitch, teeth, rr, rs, psi, model.tip(teeth))
    th_s = math.atan2(-math.sin(psi), math.cos(psi))
    th_t = math.atan2(dtb, dta)
    ce = np.array([cea, ceb])
    # seat (concave; material outside the circle r_s): a tangent polygon, its vertices in
    # the material; points rs (-cos φ, sin φ) = rs (cos(π - φ), -sin(π - φ))... φ from -ψ to ψ
    seat, l_seat = _arc_polygon(np.zeros(2), rs, math.pi + psi, math.pi - psi, seat_faces, True)
    # flank (convex; material inside r_e): its chords, the ends on S and on the corner T
    up, l_flank = _arc_polygon(ce, re, th_s, th_t, flank_faces, False)          # b > 0 side
    down = _arc_polygon(ce, re, th_s, th_t, flank_faces, False, sign_b=-1.0)[0][::-1]
    # the seat runs from b < 0 to b > 0 (counter-clockwise); joined to the flanks' ends S
    assert seat[0, 1] < 0 < seat[-1, 1]
    seat = np.vstack([down[-1:], seat, up[:1]])
    classes = {"seat": [], "flank": [], "tip": []}
    corners = []
    for g in range(teeth):
        # the gap frame (a radial, b tangential, origin at the seat centre) turned to gap g
        cb, sb = math.cos(2 * math.pi * g / teeth), math.sin(2 * math.pi * g / teeth)
        rot = np.array([[cb, -sb], [sb, cb]])

        def world(p, rot=rot):
            return (p + np.array([rad, 0.0])) @ rot.T

        for name, pts in (("flank", down), ("seat", seat), ("flank", up)):
            w = world(pts)
            classes[name] += [np.r_[w[k], w[k + 1]] for k in range(len(w) - 1)
                              if np.hypot(*(w[k + 1] - w[k])) > 1e-9]
        corners.append((world(down[:1])[0], world(up[-1:])[0]))
    for g in range(teeth):
        classes["tip"].append(np.r_[corners[g][1], corners[(g + 1) % teeth][0]])
    l_tip = float(np.hypot(*(classes["tip"][0][2:] - classes["tip"][0][:2])))
    return {l_seat: np.array(classes["seat"]), l_flank: np.array(classes["flank"]),
            l_tip: np.array(classes["tip"])}


def near_rollers(model, state, duration, margin=3):
    """Per wheel, the rollers that can touch it within ``duration`` [s] of ``state``: those
    within a pitch of its pitch circle now, the ``travel + margin`` links that run onto it
    (``travel`` the links the chain passes at the driver's final speed) and ``margin``
    links on the other side, as sorted index arrays. A broad phase by hand: Exudyn's curve
    contact checks every circle against every segment; a roller that cannot reach a wheel
    in the run is left out of that wheel's contact."""
    n = model.links
    w0 = model.wheels[0]
    rad0 = model.pitch / (2 * math.sin(math.pi / w0.teeth))
    travel = int(math.ceil(abs(w0.angular_velocity) * rad0 * duration / model.pitch))
    # the chain's direction in index terms: on the driver, does pin i + 1 lie ahead of pin i
    # in its turning sense (counter-clockwise for a positive speed)?
    c0 = state.wp[0, [K.W_CX, K.W_CY]]
    i0 = int(np.argmin(np.hypot(*(state.pos - c0).T)))
    a, b = state.pos[i0] - c0, state.pos[(i0 + 1) % n] - state.pos[i0]
    ahead = 1 if (a[0] * b[1] - a[1] * b[0]) * (1.0 if w0.angular_velocity >= 0 else -1.0) > 0 else -1
    out = []
    for j, w in enumerate(model.wheels):
        rad = model.pitch / (2 * math.sin(math.pi / w.teeth))
        centre = state.wp[j, [K.W_CX, K.W_CY]]
        close = np.nonzero(np.hypot(*(state.pos - centre).T) < rad + model.pitch)[0]
        # the pins now behind the wheel's arc reach it: indices i - ahead * k
        idx = {(i - ahead * k) % n for i in close for k in range(-margin, travel + margin + 1)}
        out.append(np.array(sorted(idx)))
    return out


def build(model, state, rigid=False, near=None, friction_zone=None, seat_faces=SEAT_FACES,
          flank_faces=FLANK_FACES, contact_damping=None):
    """The Exudyn system of the drive at chaindrive's assembled ``state``: (SystemContainer,
    MainSystem, handles). ``near``: per wheel the rollers its contacts check
    (:func:`near_rollers`; default all); ``friction_zone``: the friction's regularisation
    velocity [m/s] (default ``model.friction_velocity``)."""
    import exudyn as exu
    from exudyn import itemInterface as ii

    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    m, rr = model.link_mass, model.roller_radius
    g = model.gravity
    ground_node = mbs.AddNode(ii.NodePointGround())
    m_ground = mbs.AddMarker(ii.MarkerNodeCoordinate(nodeNumber=ground_node, coordinate=0))
    wheels = []
    for j, w in enumerate(model.wheels):
        cx, cy = state.wp[j, K.W_CX], state.wp[j, K.W_CY]
        node = mbs.AddNode(ii.NodeRigidBody2D(referenceCoordinates=[cx, cy, state.ws[j, K.S_THETA]]))
        body = mbs.AddObject(ii.ObjectRigidBody2D(mass=1.0, inertia=w.inertia,
                                                  nodeNumber=node))
        for coord in (0, 1):
            mc = mbs.AddMarker(ii.MarkerNodeCoordinate(nodeNumber=node, coordinate=coord))
            mbs.AddObject(ii.CoordinateConstraint(markerNumbers=[m_ground, mc]))
        wheels.append((node, body, mbs.AddMarker(ii.MarkerNodeRigid(nodeNumber=node)),
                       mbs.AddMarker(ii.MarkerNodeCoordinate(nodeNumber=node, coordinate=2))))
    rollers, markers = [], []
    for x, y in state.pos:
        node = mbs.AddNode(ii.NodeRigidBody2D(referenceCoordinates=[x, y, 0.0]))
        mbs.AddObject(ii.ObjectRigidBody2D(mass=m, inertia=0.5 * m * rr * rr,
                                           nodeNumber=node))
        mk = mbs.AddMarker(ii.MarkerNodeRigid(nodeNumber=node))
        mbs.AddLoad(ii.Force(markerNumber=mk, loadVector=[m * g[0], m * g[1], 0.0]))
        rollers.append(node)
        markers.append(mk)
    n = len(rollers)
    links = []
    for i in range(n):
        a, b = markers[i], markers[(i + 1) % n]
        if rigid:
            links.append(mbs.AddObject(ii.ObjectConnectorDistance(
                markerNumbers=[a, b], distance=float(np.hypot(*(state.pos[(i + 1) % n] - state.pos[i]))))))
        else:
            links.append(mbs.AddObject(ii.ObjectConnectorSpringDamper(
                markerNumbers=[a, b], referenceLength=model.pitch, stiffness=model.link_stiffness,
                damping=model.link_damping)))
    kc = model.contact_stiffness
    cc = model.contact_damping if contact_damping is None else contact_damping
    zone = model.friction_velocity if friction_zone is None else friction_zone
    for j, w in enumerate(model.wheels):
        mk = markers if near is None else [markers[i] for i in near[j]]
        for length, seg in tooth_segments(model, w.teeth, seat_faces, flank_faces).items():
            nseg = len(seg)
            data = mbs.AddNode(ii.NodeGenericData(initialCoordinates=[-1, 0, 0] * nseg,
                                                  numberOfDataCoordinates=3 * nseg))
            mbs.AddObject(ii.ObjectContactCurveCircles(
                markerNumbers=[wheels[j][2]] + mk, nodeNumber=data, circlesRadii=[rr] * len(mk),
                segmentsData=exu.MatrixContainer(seg), contactStiffness=kc / length,
                contactDamping=cc / length, dynamicFriction=model.friction,
                frictionProportionalZone=zone))
    # the driver: a stiff angle servo to the ramp's angle (offset set before each step)
    ground_angle = mbs.AddMarker(ii.MarkerNodeCoordinate(nodeNumber=ground_node, coordinate=0))
    servo = mbs.AddObject(ii.ObjectConnectorCoordinateSpringDamperExt(
        markerNumbers=[ground_angle, wheels[0][3]], stiffness=SERVO_K, damping=SERVO_C,
        offset=0.0, velocityOffset=0.0))  # marker coordinates are displacements
    mbs.AddLoad(ii.Torque(markerNumber=wheels[1][2], loadVector=[0.0, 0.0, model.wheels[1].torque]))
    return sc, mbs, {"rollers": rollers, "links": links, "wheels": wheels, "servo": servo}


def ramp(w0, t):
    """(angle advance [rad], speed [rad/s]) of chaindrive's linear speed ramp at ``t``."""
    om, tr = w0.angular_velocity, w0.ramp_time
    if tr <= 0 or t >= tr:
        return om * (t - 0.5 * tr if tr > 0 else t), om
    return 0.5 * om * t * t / tr, om * t / tr


def settings(dt, duration, solver=SOLVER, spectral_radius=0.9):
    """Exudyn simulation settings: ``solver`` 'implicit' (generalized-α, sparse, modified
    Newton, as Exudyn's chain example) or an explicit one ('VelocityVerlet', 'RK44', ...)."""
    import exudyn as exu

    ss = exu.SimulationSettings()
    ti = ss.timeIntegration
    ti.numberOfSteps = int(round(duration / dt))
    ti.endTime = ti.numberOfSteps * dt
    ti.verboseMode = 0
    ss.solutionSettings.writeSolutionToFile = False
    ss.solutionSettings.writeInitialValues = False
    ss.linearSolverType = exu.LinearSolverType.EigenSparse
    ss.displayStatistics = False
    ss.displayComputationTime = False
    if solver == "implicit":
        ti.generalizedAlpha.spectralRadius = spectral_radius
        ti.newton.useModifiedNewton = True
    else:
        ti.explicit.computeMassMatrixInversePerBody = True
        ti.explicit.computeEndOfStepAccelerations = False
    return ss


def run(model, state, duration, dt, probe, tight_mid, sample, steady, rigid=False, solver=SOLVER,
        spectral_radius=0.9, name=None, **options):
    """One timed Exudyn run from chaindrive's assembled ``state``: the same keys as the
    MuJoCo peer's rows (``benchmarks/simulate.py``), or None when it failed (diverged, the
    chain off the wheels). Sampled every ``sample`` s by Exudyn's sensors (stored in
    memory); CPU time (``time.process_time``) of ``SolveDynamic``."""
    import exudyn as exu
    from exudyn import itemInterface as ii

    sc, mbs, h = build(model, state, rigid=rigid, **options)
    ovt = exu.OutputVariableType
    pos = [mbs.AddSensor(ii.SensorNode(nodeNumber=nd, storeInternal=True, writeToFile=False,
                                       outputVariableType=ovt.Position)) for nd in h["rollers"]]
    vel = [mbs.AddSensor(ii.SensorNode(nodeNumber=nd, storeInternal=True, writeToFile=False,
                                       outputVariableType=ovt.Velocity)) for nd in h["rollers"]]
    force = [mbs.AddSensor(ii.SensorObject(objectNumber=o, storeInternal=True, writeToFile=False,
                                           outputVariableType=ovt.Force)) for o in h["links"]]
    w1 = mbs.AddSensor(ii.SensorNode(nodeNumber=h["wheels"][1][0], storeInternal=True,
                                     writeToFile=False, outputVariableType=ovt.AngularVelocity))
    w0 = model.wheels[0]
    servo = h["servo"]

    def pre_step(mbs, t):
        adv, om = ramp(w0, t + dt)  # chaindrive sets the driver speed at the end of the step
        mbs.SetObjectParameter(servo, "offset", adv)
        mbs.SetObjectParameter(servo, "velocityOffset", om)
        return True

    mbs.SetPreStepUserFunction(pre_step)
    mbs.Assemble()
    ss = settings(dt, duration, solver, spectral_radius)
    ss.solutionSettings.sensorsWritePeriod = sample
    t0 = time.process_time()
    try:
        if solver == "implicit":
            ok = mbs.SolveDynamic(ss)
        else:
            ok = mbs.SolveDynamic(ss, solverType=getattr(exu.DynamicSolverType, solver))
    except Exception as exc:  # Exudyn raises on a failed Newton step or a NaN
        print(f"    exudyn dt = {dt:g}: {type(exc).__name__}: {str(exc).splitlines()[0][:120]}")
        return None
    cpu = time.process_time() - t0
    if ok is False:
        return None
    xy = np.stack([mbs.GetSensorStoredData(s)[:, 1:3] for s in pos], axis=1)  # (T, n, 2)
    vv = np.stack([mbs.GetSensorStoredData(s)[:, 1:3] for s in vel], axis=1)
    times = mbs.GetSensorStoredData(pos[0])[:, 0]
    # the connectors' force, positive in compression (measured: -3135 N on the tight span
    # of the stiff model): the link tension is its negative
    ff = -np.stack([mbs.GetSensorStoredData(s)[:, 1] for s in force], axis=1)
    wheel1 = mbs.GetSensorStoredData(w1)[:, 3]
    if not (np.all(np.isfinite(xy)) and np.all(np.isfinite(ff))):
        print(f"    exudyn dt = {dt:g}: non-finite state")
        return None
    ib = np.argmin(np.sum((xy - probe[:2]) ** 2, axis=2), axis=1)
    rows = np.arange(len(times))
    v = vv[rows, ib, 0] * probe[2] + vv[rows, ib, 1] * probe[3]
    mid = 0.5 * (xy + np.roll(xy, -1, axis=1))
    il = np.argmin(np.sum((mid - tight_mid) ** 2, axis=2), axis=1)
    ten = ff[rows, il]
    sel = times >= steady
    nsteps = ss.timeIntegration.numberOfSteps
    res = {
        "name": name or ("exudyn rigid" if rigid else "exudyn stiff"),
        "dt": dt, "steps": nsteps, "wall": cpu,
        "link_steps_per_s": nsteps * model.links / cpu,
        "wall_per_sim_s": cpu / (nsteps * dt),
        "v_mean": float(np.mean(v[sel])), "v_peak": float(np.max(v[sel])),
        "tight_mean": float(np.mean(ten[sel])), "tight_max": float(np.max(ten[sel])),
        "wheel1": float(np.mean(wheel1[sel])),
    }
    if not abs(res["wheel1"] / w0.angular_velocity - 1.0) < 0.05:
        print(f"    exudyn dt = {dt:g}: driven wheel at {res['wheel1']:.3f} rad/s, chain off")
        return None
    return res


def ladder(model, state, duration, probe, tight_mid, sample, steady, converged, steps=LADDER):
    """Rows of the step ladder (each a :func:`run` in the configuration ``CONFIG``, the
    broad phase :func:`near_rollers`), stopping at the first step converged against its
    half (``converged(rows)``, ``benchmarks/simulate.py``'s test)."""
    rows: list[dict] = []
    near = near_rollers(model, state, duration)
    for dt in steps:
        res = run(model, state, duration, dt, probe, tight_mid, sample, steady, near=near, **CONFIG)
        status = "failed" if res is None else "ran"
        print(f"  exudyn stiff links ({SOLVER}) dt = {dt:g} s: {status}", flush=True)
        rows += [] if res is None else [res]
        if len(rows) > 1 and converged(rows) is not None:
            break
    return rows
