"""``chaindrive contact``, ``tooth-strength``, ``fretting``, ``bolts``: strength and life.

Text output in MPa, mm, arc minutes; ``--json`` prints every computed figure in SI
units (N, m, Pa, rad, s), the same numbers the Python API returns. Bad input gives a
one-line ``error: ...`` naming the field and its range, exit code 2; a failed
strength check (a safety factor below 1) exits with 1.
"""

from __future__ import annotations

from typing import Any

import typer

from ..display import mm, mpa, um
from ..errors import InputError
from .app import OPTION_ALIASES, app, echo_json, exit_code, print_rows, quantity, unit_help


def _chain(name):
    from .. import chains

    return chains.get(name)


def _rows(title, rows):
    print_rows(title, rows)


def _mpa(v):
    return "-" if v is None else f"{mpa(v):.1f} MPa"


def _f(v, fmt="{:.2f}"):
    """A dimensionless figure (safety factor, ratio), marked as such."""
    return "-" if v is None else fmt.format(v) + " (ratio)"


OPTION_ALIASES["contact"] = {
    "wear_factor": "--k-phi", "radius_2": "--seat-radius", "max_skew": "--skew",
    "poisson_ratio": "--poisson", "poisson_ratio_1": "--poisson", "poisson_ratio_2": "--poisson",
    "elastic_modulus": "--modulus", "elastic_modulus_1": "--modulus", "elastic_modulus_2": "--modulus",
}


@app.command("contact")
def contact_command(
    load: str = typer.Option(..., "--load", help=unit_help("Nominal roller load Q_nom (Garshniev & Maksymovych eqs 1-2).", "N", "5 kN")),
    chain: str | None = typer.Option(None, "--chain", "-c", help="Roller chain from the catalogue, e.g. 16B (gives pitch, D_p = d1, L_p = b1)."),
    pitch: str | None = typer.Option(None, "--pitch", help=unit_help("Chain pitch for gamma (Garshniev & Maksymovych table, 12.7...25.4 mm).", "m", "25.4 mm")),
    roller_diameter: str | None = typer.Option(None, "--roller-diameter", help=unit_help("Roller diameter D_p.", "m", "15.88 mm")),
    seat_radius: str | None = typer.Option(None, "--seat-radius", help=unit_help("Tooth profile radius r1 at the contact; default ISO 606:2015 5.4.2 r_i,min = 0.505 d1.", "m", "8.1 mm")),
    length: str | None = typer.Option(None, "--length", help=unit_help("Roller length L_p; default the chain's inner width b1.", "m", "17 mm")),
    teeth: int | None = typer.Option(None, "--teeth", help="Sprocket teeth z (dimensionless count): with --contact convex and no --seat-radius, r1 = ISO 606:2015 5.4.2 r_e,min = 0.12 d1 (z + 2)."),
    contact: str = typer.Option("concave", "--contact", help="'concave' roller in the seat (1/rho = 2/D_p - 1/r1) or 'convex' flank (+), Garshniev & Maksymovych rho."),
    skew: str | None = typer.Option(None, "--skew", help=unit_help("Largest skew phi_p,max (Garshniev & Maksymovych; measured 0 deg 42'...3 deg 26').", "arcmin, deg or rad", "50 arcmin")),
    skew_dh: str | None = typer.Option(None, "--skew-dh", help=unit_help("Measured probe depth difference Delta h: phi = atan(Delta h / B) (Garshniev & Maksymovych).", "m", "0.2 mm")),
    skew_base: str | None = typer.Option(None, "--skew-base", help=unit_help("Probe base B for --skew-dh (Garshniev & Maksymovych).", "m", "20 mm")),
    k_phi: float = typer.Option(0.65, "--k-phi", help="Wear factor K_phi (dimensionless), Garshniev & Maksymovych range 0.6...0.7: phi_p = phi_p,max K_phi."),
    gamma: float | None = typer.Option(None, "--gamma", help="gamma directly instead of Garshniev & Maksymovych pitch table; a bare number in 1/arcmin^2, e.g. 0.0004."),
    outside: str = typer.Option("warn", "--gamma-outside", help="Pitch outside 12.7...25.4 mm: 'warn' (extrapolate gamma ~ 1/p) or 'raise'."),
    modulus: str = typer.Option("210 GPa", "--modulus", help=unit_help("Young's modulus E of roller and tooth (Hertz, Johnson 1985 eq. 4.45).", "Pa", "210 GPa")),
    poisson: float = typer.Option(0.3, "--poisson", help="Poisson's ratio (dimensionless); 0.3 gives Garshniev & Maksymovych's 0.418."),
    as_json: bool = typer.Option(False, "--json", help="Print every figure as JSON in SI units (N, m, Pa, rad)."),
) -> None:
    """Roller–tooth contact stress with skew (Garshniev & Maksymovych).

    sigma = sqrt(Q_n E* / (pi L_p rho)) = 0.418 sqrt(Q_n E / (L_p rho)) for steel (eq. 1);
    Q_n = Q_nom (1 + gamma phi_p^2) (eq. 2), phi_p in arc minutes; relative life
    L/L0 = (Q_n/Q_nom)^-k, k = 1 wear (Archard), k = 10/3 rolling fatigue (ISO 281).
    """
    from ..strength import ARCMIN, roller_contact_stress, skew_from_measurement

    q = quantity(load, "N", "load")
    c = _chain(chain) if chain else None
    p = quantity(pitch, "m", "pitch") if pitch else (c.pitch if c else None)
    d = quantity(roller_diameter, "m", "roller_diameter") if roller_diameter else (c.roller_diameter if c else None)
    if d is None:
        raise InputError("roller_diameter is needed (--roller-diameter > 0 m, or --chain of a roller chain)")
    if seat_radius:
        r1 = quantity(seat_radius, "m", "seat_radius")
    elif contact == "convex":
        if teeth is None:
            raise InputError("a convex flank needs --seat-radius (> 0 m) or --teeth (>= 9) for ISO 606 r_e,min")
        from ..geometry.sprocket import flank_radius_limits

        r1 = float(flank_radius_limits(d, teeth)[0])
    else:
        r1 = 0.505 * d
    ln = quantity(length, "m", "length") if length else (c.inner_width if c else None)
    if ln is None:
        raise InputError("length is needed (--length > 0 m, or --chain with an inner width)")
    if skew is not None and skew_dh is not None:
        raise InputError("give either --skew or --skew-dh/--skew-base, not both")
    if skew_dh is not None:
        if skew_base is None:
            raise InputError("skew_base (--skew-base > 0 m) is needed with --skew-dh")
        phi = skew_from_measurement(quantity(skew_dh, "m", "skew_dh"), quantity(skew_base, "m", "skew_base"))
    else:
        phi = quantity(skew, "rad", "skew", examples=("arcmin", "deg")) if skew else 0.0
    e = quantity(modulus, "Pa", "modulus", examples=("GPa", "MPa"))
    r = roller_contact_stress(q, d, r1, ln, contact=contact, max_skew=phi, wear_factor=k_phi, pitch=p,
                              gamma=gamma, elastic_modulus=e, poisson_ratio=poisson, outside=outside)
    if as_json:
        out = r.to_dict()
        out.update(pitch=p, roller_diameter=d, seat_radius=r1, length=ln)
        echo_json(out)
        return
    _rows("Roller–tooth contact (Garshniev & Maksymovych)", [
        ("load Q_nom", f"{q:.1f} N", "input"),
        ("skew phi_max", f"{phi / ARCMIN:.1f} arcmin", "input / atan(dh/B)"),
        ("design skew phi_p", f"{r.design_skew / ARCMIN:.1f} arcmin", "phi_max K_phi"),
        ("gamma", f"{r.gamma:.5f} /arcmin^2", "Garshniev & Maksymovych table"),
        ("load factor Q_n/Q", _f(r.load_factor, "{:.3f}"), "Garshniev & Maksymovych eq. (2)"),
        ("rho", f"{mm(r.reduced_radius):.3f} mm", "1/rho = 2/D_p -+ 1/r1"),
        ("sigma at no skew", _mpa(r.stress_unskewed), "Hertz / Garshniev & Maksymovych eq. (1)"),
        ("sigma with skew", _mpa(r.stress), "Garshniev & Maksymovych eq. (1)-(3)"),
        ("life ratio, wear", _f(r.relative_life_wear, "{:.3f}"), "(Q_n/Q)^-1 Archard"),
        ("life ratio, fatigue", _f(r.relative_life_fatigue, "{:.4f}"), "(Q_n/Q)^-10/3 ISO 281"),
    ])


@app.command("tooth-strength")
def tooth_strength_command(
    weight: str = typer.Option(..., "--weight", help=unit_help("Tractor weight G_T (Sharipov p. 34: P = 0.65 G_T phi).", "N", "60 kN")),
    adhesion: float = typer.Option(1.0, "--adhesion", help="Adhesion coefficient phi (dimensionless) (Sharipov: 1.0), 0 < phi <= 1.5."),
    rims: int = typer.Option(1, "--rims", help="Toothed rims i: 1 or 2 (dimensionless count) (Sharipov: P_P = P / i)."),
    pitch: str = typer.Option(..., "--pitch", help=unit_help("Track pitch t.", "m", "170 mm")),
    teeth: int = typer.Option(..., "--teeth", help="Number of teeth z >= 3 (dimensionless count)."),
    pin_radius: str = typer.Option(..., "--pin-radius", help=unit_help("Pin radius r_pin (Sharipov p. 34).", "m", "25 mm")),
    link: str = typer.Option("built-up", "--link", help="'built-up' or 'cast' track links (Sharipov tip radius range)."),
    root_factor: float | None = typer.Option(None, "--root-factor", help="r_seat / r_pin in 1.1...1.3 (dimensionless, Sharipov), default 1.2."),
    tip_factor: float | None = typer.Option(None, "--tip-factor", help="(R_tip - R_0) / r_pin (dimensionless; Sharipov: 0.2...0.5 built-up, 0.8...1.2 cast)."),
    tooth_width: str = typer.Option(..., "--tooth-width", help=unit_help("Tooth width b (bending section and contact length).", "m", "60 mm")),
    hardness: float | None = typer.Option(None, "--hardness", help="Surface hardness as a bare number in HRC, e.g. 52; Sharipov: 48...60 (outside: warning)."),
    allowable_bending: str | None = typer.Option(None, "--allowable-bending", help=unit_help("Allowable bending stress, user value.", "Pa", "400 MPa")),
    allowable_contact: str | None = typer.Option(None, "--allowable-contact", help=unit_help("Allowable contact stress, user value.", "Pa", "1200 MPa")),
    contact: str = typer.Option("convex", "--contact", help="Pin on the convex flank (radius t - r_seat) or in the 'concave' seat (Hertz, Johnson 1985 eq. 4.45)."),
    kt: float = typer.Option(1.0, "--kt", help="Root stress concentration factor K_t >= 1 (dimensionless) (Lewis cantilever, Shigley 9th ed. 14-1)."),
    as_json: bool = typer.Option(False, "--json", help="Print every figure as JSON in SI units (N, m, Pa)."),
) -> None:
    """Tooth of a track drive wheel in bending and contact (Sharipov, p. 34).

    P_P = 0.65 G_T phi / i at the tooth tip; sigma_F = K_t 6 P_P h / (b s^2) with
    s = t - 2 r_seat, h = R_tip - R_o cos(pi/z) (cantilever, Lewis-type); sigma_H Hertz
    line contact pin/flank.
    """
    from ..geometry.track_wheel import TrackDriveWheel
    from ..strength import track_tooth_check

    w = TrackDriveWheel(pitch=quantity(pitch, "m", "pitch"), teeth=teeth,
                        pin_radius=quantity(pin_radius, "m", "pin_radius"), link=link,
                        root_factor=root_factor, tip_factor=tip_factor)
    r = track_tooth_check(w, quantity(weight, "N", "weight"), quantity(tooth_width, "m", "tooth_width"),
                          adhesion=adhesion, rims=rims, hardness=hardness,
                          allowable_bending=quantity(allowable_bending, "Pa", "allowable_bending"),
                          allowable_contact=quantity(allowable_contact, "Pa", "allowable_contact"),
                          contact=contact, stress_concentration=kt)
    if as_json:
        echo_json(r.to_dict())
    else:
        _rows("Track drive wheel tooth (Sharipov)", [
            ("design force P_P", f"{r.design_force:.0f} N", "0.65 G_T phi / i"),
            ("root thickness s", f"{mm(r.root_thickness):.2f} mm", "t - 2 r_seat"),
            ("lever arm h", f"{mm(r.lever_arm):.2f} mm", "R_tip - R_o cos(pi/z)"),
            ("bending stress", _mpa(r.bending_stress), "K_t 6 P h / (b s^2)"),
            ("contact stress", _mpa(r.contact_stress), "Hertz line contact"),
            ("bending safety", _f(r.bending_safety), "allowable / actual"),
            ("contact safety", _f(r.contact_safety), "allowable / actual"),
            ("passes", "yes" if r.passes else "NO", ""),
        ])
    if not r.passes:
        exit_code(1)


@app.command("fretting")
def fretting_command(
    load: str = typer.Option(..., "--load", help=unit_help("Amplitude of the cyclic chain load on the pin (drives the pin bending).", "N", "5 kN")),
    chain: str | None = typer.Option(None, "--chain", "-c", help="Multi-strand chain, e.g. 16B-3 (pin diameter d2, transverse pitch pt, b1 from ISO 606)."),
    pin_diameter: str | None = typer.Option(None, "--pin-diameter", help=unit_help("Pin diameter d2.", "m", "8.28 mm")),
    transverse_pitch: str | None = typer.Option(None, "--transverse-pitch", help=unit_help("Transverse pitch pt.", "m", "31.88 mm")),
    strands: int | None = typer.Option(None, "--strands", help="Number of rows n, 1...10 (dimensionless count)."),
    inner_width: str | None = typer.Option(None, "--inner-width", help=unit_help("Width between inner plates b1.", "m", "17.02 mm")),
    end_fixity: str = typer.Option("pinned", "--end-fixity", help="Pin in the outer plates: 'pinned' or 'clamped' (Euler-Bernoulli beam model)."),
    roughness: str = typer.Option("0.8 um", "--roughness", help=unit_help("Surface roughness Ra (Vikulov eq. 1).", "m", "0.8 um")),
    frequency: str = typer.Option("10 Hz", "--frequency", help=unit_help("Vibration frequency f (Vikulov eq. 1).", "Hz", "10 Hz")),
    k1: str | None = typer.Option(None, "--k1", help=unit_help("K1 of tau = K1 Ra exp(-k2 A N f / Ra) (Vikulov eq. 1); empirical.", "s/m", "1e9 s/m")),
    k2: str | None = typer.Option(None, "--k2", help=unit_help("k2 = -K2 > 0 (Vikulov eq. 1 with the sign made explicit); empirical.", "s/N", "1e-9 s/N")),
    normal_load: str | None = typer.Option(None, "--normal-load", help=unit_help("Normal load N in the joint; default load / strands.", "N", "2 kN")),
    as_json: bool = typer.Option(False, "--json", help="Print every figure as JSON in SI units (N, m, Pa, rad, s)."),
) -> None:
    """Pin bending and fretting latent period of a multi-row chain (Vikulov).

    Compared with and without working intermediate plates.

    Slip A = max pin slope x d/2 (Euler-Bernoulli pin across the rows, tiny FE);
    tau = K1 Ra exp(-k2 A N f / Ra) (eq. 1, K2 = -k2).
    """
    from ..strength import MultiRowPin, fretting_comparison

    if chain:
        pin = MultiRowPin.from_chain(_chain(chain), end_fixity=end_fixity)
    else:
        if pin_diameter is None or transverse_pitch is None or strands is None or inner_width is None:
            raise InputError("give --chain or all of --pin-diameter, --transverse-pitch, --strands, --inner-width (> 0)")
        pin = MultiRowPin(quantity(pin_diameter, "m", "pin_diameter"), quantity(transverse_pitch, "m", "transverse_pitch"),
                          strands, quantity(inner_width, "m", "inner_width"), end_fixity=end_fixity)
    f = quantity(load, "N", "load")
    a = pin.bending(f, intermediate_plates=False)
    b = pin.bending(f, intermediate_plates=True)
    out = {
        "pin_diameter": pin.pin_diameter, "transverse_pitch": pin.transverse_pitch, "strands": pin.strands,
        "inner_width": pin.inner_width, "end_fixity": pin.end_fixity, "load": f,
        "without_intermediate_plates": {k: v for k, v in a.to_dict().items() if k != "beam"},
        "with_intermediate_plates": {k: v for k, v in b.to_dict().items() if k != "beam"},
        "slip_ratio": a.slip_amplitude / b.slip_amplitude,
    }
    if (k1 is None) != (k2 is None):
        raise InputError("give both --k1 (> 0 s/m) and --k2 (> 0 s/N) for the latent period, or neither")
    fr: dict[str, Any] | None = None
    if k1 is not None and k2 is not None:
        nl = quantity(normal_load, "N", "normal_load") if normal_load else None
        c = fretting_comparison(pin, f, quantity(roughness, "m", "roughness", examples=("um", "mm")), quantity(frequency, "Hz", "frequency"),
                                quantity(k1, "s/m", "k1"), quantity(k2, "s/N", "k2"), normal_load=nl)
        fr = c.to_dict()
        out["fretting"] = fr
    if as_json:
        echo_json(out)
        return
    rows = [
        ("slip A without", f"{um(a.slip_amplitude):.3f} um", "max slope x d/2, plates idle"),
        ("slip A with", f"{um(b.slip_amplitude):.3f} um", "intermediate plates support the pin"),
        ("slip ratio", _f(out['slip_ratio']), "without / with"),
        ("pin stress without", _mpa(a.max_stress), "32 M / (pi d^3)"),
        ("pin stress with", _mpa(b.max_stress), "32 M / (pi d^3)"),
    ]
    if fr is not None:
        rows += [
            ("tau without", f"{fr['latent_without']:.4g} s", "Vikulov eq. (1)"),
            ("tau with", f"{fr['latent_with']:.4g} s", "Vikulov eq. (1)"),
            ("life ratio", _f(fr['life_ratio'], "{:.4g}"), "tau_with / tau_without"),
        ]
    _rows(f"Multi-row pin, {pin.strands} rows (Vikulov)", rows)


@app.command("bolts")
def bolts_command(
    bolt_circle_radius: str = typer.Option(..., "--bolt-circle-radius", help=unit_help("Bolt circle radius R_b.", "m", "250 mm")),
    bolts: int = typer.Option(..., "--bolts", help="Number of bolts n, 1...1000 (dimensionless count)."),
    torque: str | None = typer.Option(None, "--torque", help=unit_help("Torque on the rim.", "N*m", "7 kN*m")),
    force: str | None = typer.Option(None, "--force", help=unit_help("Instead of --torque: tooth force P_P (Sharipov p. 34) ...", "N", "20 kN")),
    pitch_radius: str | None = typer.Option(None, "--pitch-radius", help=unit_help("... and pitch radius R_0: T = P_P R_0.", "m", "355 mm")),
    joint: str = typer.Option("fitted", "--joint", help="'fitted' bolts in shear (Shigley 9th ed. 8-12) or 'friction' joint (VDI 2230-1 step R2)."),
    shank_diameter: str | None = typer.Option(None, "--shank-diameter", help=unit_help("Fitted shank diameter d.", "m", "17 mm")),
    shear_planes: int = typer.Option(1, "--shear-planes", help="Shear planes m (fitted), 1...10 (dimensionless count)."),
    plate_thickness: str | None = typer.Option(None, "--plate-thickness", help=unit_help("Thinnest clamped part t_min for bearing (fitted).", "m", "20 mm")),
    allowable_shear: str | None = typer.Option(None, "--allowable-shear", help=unit_help("Allowable shear stress.", "Pa", "200 MPa")),
    allowable_bearing: str | None = typer.Option(None, "--allowable-bearing", help=unit_help("Allowable bearing pressure.", "Pa", "300 MPa")),
    friction: float = typer.Option(0.15, "--friction", help="Friction coefficient mu (dimensionless, friction joint), 0 < mu <= 1."),
    friction_faces: int = typer.Option(1, "--friction-faces", help="Frictional interfaces q (friction joint), 1...10 (dimensionless count)."),
    slip_safety: float = typer.Option(1.25, "--slip-safety", help="Safety against slip S >= 1 (dimensionless) (VDI 2230-1: 1.2 static, 1.8 alternating)."),
    diameter: str | None = typer.Option(None, "--diameter", help=unit_help("Nominal thread diameter d for A_s (ISO 898-1).", "m", "16 mm")),
    thread_pitch: str | None = typer.Option(None, "--thread-pitch", help=unit_help("Thread pitch P for A_s (ISO 898-1).", "m", "2 mm")),
    yield_strength: str | None = typer.Option(None, "--yield-strength", help=unit_help("Bolt R_p0.2 (ISO 898-1: 8.8 640 MPa).", "Pa", "640 MPa")),
    as_json: bool = typer.Option(False, "--json", help="Print every figure as JSON in SI units (N, m, Pa)."),
) -> None:
    """Bolts of a toothed rim under the transmitted torque (Sharipov Fig. 14).

    F = T / (n R_b) per bolt; fitted: tau = 4F/(m pi d^2), p = F/(d t); friction:
    F_V = S T / (mu q n R_b), sigma_V = F_V / A_s (VDI 2230-1 R2, ISO 898-1 A_s).
    """
    from ..strength import bolt_stress_area, fitted_bolt_check, friction_bolt_preload

    if torque is not None:
        t = quantity(torque, "N*m", "torque")
    elif force is not None and pitch_radius is not None:
        t = quantity(force, "N", "force") * quantity(pitch_radius, "m", "pitch_radius")
    else:
        raise InputError("give --torque (> 0 N m) or both --force and --pitch-radius (> 0)")
    rb = quantity(bolt_circle_radius, "m", "bolt_circle_radius")
    if joint == "fitted":
        if shank_diameter is None:
            raise InputError("shank_diameter (--shank-diameter > 0 m) is needed for fitted bolts")
        fitted = fitted_bolt_check(t, rb, bolts, quantity(shank_diameter, "m", "shank_diameter"), shear_planes=shear_planes,
                              plate_thickness=quantity(plate_thickness, "m", "plate_thickness"),
                              allowable_shear=quantity(allowable_shear, "Pa", "allowable_shear"),
                              allowable_bearing=quantity(allowable_bearing, "Pa", "allowable_bearing"))
        rows = [("force per bolt", f"{fitted.bolt_force:.0f} N", "T / (n R_b)"),
                ("shear stress", _mpa(fitted.shear_stress), "4F/(m pi d^2)"),
                ("bearing stress", _mpa(fitted.bearing_stress), "F/(d t)"),
                ("shear safety", _f(fitted.shear_safety), ""), ("bearing safety", _f(fitted.bearing_safety), "")]
        result: Any = fitted
    elif joint == "friction":
        a_s: float | None = None
        if diameter is not None or thread_pitch is not None:
            if diameter is None or thread_pitch is None:
                raise InputError("give both --diameter and --thread-pitch (> 0 m) for the stress area")
            a_s = float(bolt_stress_area(quantity(diameter, "m", "diameter"), quantity(thread_pitch, "m", "thread_pitch")))
        r = friction_bolt_preload(t, rb, bolts, friction, friction_faces=friction_faces, slip_safety=slip_safety,
                                  stress_area=a_s, yield_strength=quantity(yield_strength, "Pa", "yield_strength"))
        rows = [("force per bolt", f"{r.bolt_force:.0f} N", "T / (n R_b)"),
                ("required preload", f"{r.required_preload:.0f} N", "S T / (mu q n R_b)"),
                ("preload stress", _mpa(r.preload_stress), "F_V / A_s"),
                ("yield safety", _f(r.yield_safety), "R_p0.2 / sigma_V")]
        result = r
    else:
        raise InputError(f"joint must be 'fitted' or 'friction', got {joint!r}")
    if as_json:
        out = result.to_dict()
        out.update(torque=t, joint=joint)
        echo_json(out)
    else:
        _rows(f"Rim bolts ({joint}), torque {t:.0f} N m", rows)
    if not result.passes:
        exit_code(1)
