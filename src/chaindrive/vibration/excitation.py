"""How strongly the slack span is excited: amplitudes of the excitations and the forced response.

The tensioner paper's check says *whether* a natural frequency lies near an exciting one;
this module says *how large* the response is, so that a verdict can be read beside its
severity:

* :func:`runout_tolerance` and :func:`unequal_link_amplitude`: the published tolerances
  the eccentricity and the unequal-links excitations rest on (ISO 606:2015).
* :func:`polygon_transverse_harmonics`: the transverse motion of the point where the span
  leaves a wheel (the chordal action), as Fourier amplitudes, for a regular polygon
  (roller chain) or the bi-regular one of a round link chain (Dolipiński et al., eq. 6).
* :func:`forced_span_response`: the steady response of the slack span with its
  tensioner to a transverse motion of its ends, exact for the string model of the
  frequency equation, with a stated damping (structural, loss factor 2ζ on the tension).
* :func:`span_excitations`: all of it for one drive's wheel data, one row per excitation.

Derivations and the independent check (the planar bead model): docs/vibration.md, §6a.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._results import Result, quantity
from .._validation import check_nonnegative, check_positive, check_range, check_teeth
from .resonance import TensionerSpan, excitation_multipliers
from .tensioner import COUPLING_MODELS

__all__ = [
    "LENGTH_TOLERANCE",
    "DAMPING_RATIO",
    "AMPLIFICATION_LIMIT",
    "ExcitationResponse",
    "runout_tolerance",
    "unequal_link_amplitude",
    "polygon_transverse_harmonics",
    "forced_span_response",
    "span_excitations",
    "span_damping_rate",
]

#: Upper limit of the measured length of a roller chain over the nominal: +0.15 % (lower 0)
#: (ISO 606:2015, 3.4.4 "Length validation"). The whole of it is taken as the difference of
#: the inner and the outer link pitch: an upper bound of that difference.
LENGTH_TOLERANCE = 0.0015
#: Largest dynamic amplification of the slack span's forced response accepted for any
#: excitation: that of one undamped mode at the tensioner paper's band edge P/ω = 1.4,
#: 1/(1 − 1/1.4²) = 2.04 (the paper forbids 0.7 ≤ P/ω ≤ 1.4; a mode just outside its
#: upper edge amplifies a quasi-static end motion 2.04 times, so the paper accepts that).
AMPLIFICATION_LIMIT = 1.0 / (1.0 - 1.0 / 1.4**2)
#: Damping ratio of the span's transverse vibration assumed for the forced response (an
#: assumption, not a published value for chains: steel chain spans are lightly damped;
#: the response at resonance scales as 1/ζ).
DAMPING_RATIO = 0.02


def span_damping_rate(frequency: float, damping_ratio: float = DAMPING_RATIO) -> float:
    r"""Mass-proportional damping rate ``α`` [1/s] that gives the modes at ``frequency`` the
    damping ratio ``ζ``.

    .. math:: α = 2\,ζ\,Ω

    A viscous force ``−α m v`` on every mass of a discretised span (the transverse term
    ``c ∂y/∂t`` of Mahalingam's travelling string, ``c = α q``) damps each of its modes
    as ``exp(−α t/2)``: mode ``n`` of angular frequency ``ω_n`` has ``ζ_n = α/(2 ω_n)``
    (mass-proportional Rayleigh damping). Choosing ``α`` at the excitation frequency
    ``Ω`` gives a mode in resonance with it exactly ``ζ``, the ratio the forced
    span response (:func:`forced_span_response`) assumes; lower modes get more.

    Parameters
    ----------
    frequency : float
        ``Ω`` [rad/s], >= 0 (a drive's tooth frequency ``z ω``).
    damping_ratio : float
        ``ζ`` [-], >= 0 (default :data:`DAMPING_RATIO`).

    Returns
    -------
    float
        ``α`` [1/s].

    References
    ----------
    S. Mahalingam, "Transverse vibrations of power transmission chains", Br. J. Appl.
    Phys. 8 (1957) 145–148 (the viscous transverse term). A. K. Chopra, Dynamics of
    Structures, 4th ed., Prentice Hall 2012, §11.4.1 (mass-proportional damping,
    ``ζ_n = a_0/(2 ω_n)``).

    Examples
    --------
    >>> round(span_damping_rate(340.0), 2)   # 16B, 19 teeth at 17.9 rad/s: Ω = 340 rad/s
    13.6
    """
    check_nonnegative("frequency", frequency, "rad/s")
    check_nonnegative("damping_ratio", damping_ratio)
    return 2.0 * float(damping_ratio) * float(frequency)


@finite_guard
def runout_tolerance(diameter: ArrayLike) -> np.ndarray | float:
    r"""Radial run-out tolerance of a sprocket [m]: the eccentricity excitation's amplitude.

    Parameters
    ----------
    diameter : float or array_like
        Root (or pitch) diameter d of the wheel [m], > 0.

    Returns
    -------
    float or numpy.ndarray
        0.0008 d + 0.08 mm, at most 0.76 mm.

    .. math:: e = \min(0.0008\,d + 0.08\ \mathrm{mm},\ 0.76\ \mathrm{mm})

    Notes
    -----
    The total indicated run-out; it is used as the amplitude of the wheel's transverse
    motion at its rotation frequency (conservative: the eccentricity is half the total
    indicated run-out). Pocket wheels have no ISO tolerance; the same figure is used.

    Examples
    --------
    >>> round(runout_tolerance(0.2) * 1e3, 3)
    0.24
    >>> round(runout_tolerance(2.0) * 1e3, 3)
    0.76

    References
    ----------
    ISO 606:2015, 5.7 (radial run-out of sprockets).
    """
    d = check_positive("diameter", diameter, "m")
    out = np.minimum(0.0008 * d + 0.08e-3, 0.76e-3)
    return out if out.ndim else float(out)


@finite_guard
def unequal_link_amplitude(pitch: float, teeth: int, *, tolerance: float = LENGTH_TOLERANCE) -> float:
    r"""Transverse amplitude at z ω/2 from inner and outer links of unequal pitch [m].

    Parameters
    ----------
    pitch : float
        Chain pitch p [m].
    teeth : int
        Teeth z of the wheel the span leaves.
    tolerance : float
        Relative pitch difference Δp/p of inner and outer links (default: the ISO 606
        length tolerance, 0.15 %).

    Returns
    -------
    float
        Amplitude of the fundamental (period: two pitches) of the seat-radius change.

    .. math:: a = \frac{4}{\pi}\cdot\frac{\Delta p}{4\sin(\pi/z)} = \frac{\Delta p}{\pi \sin(\pi/z)}

    Notes
    -----
    A roller seated with the pitch p ± Δp/2 sits on a pitch circle of radius
    (p ± Δp/2)/(2 sin(π/z)): the seat radius alternates by ± Δp/(4 sin(π/z)) from link
    to link, a square wave of period two pitches whose fundamental has 4/π times that
    amplitude. An estimate of the order of magnitude (the tooth flank, not the pitch
    circle, carries the roller).

    Examples
    --------
    >>> round(unequal_link_amplitude(0.0254, 17) * 1e6, 1)
    66.0

    References
    ----------
    the tensioner paper (unequal link lengths as an excitation); ISO 606:2015, 3.4.4.
    """
    p = float(check_positive("pitch", pitch, "m"))
    z = int(check_teeth("teeth", teeth))
    tol = float(check_range("tolerance", tolerance, 0.0, 0.1))
    return float(tol * p / (np.pi * np.sin(np.pi / z)))


@finite_guard
def polygon_transverse_harmonics(radius: float, side_angles: ArrayLike, harmonics: int = 2,
                                 samples: int | None = None) -> np.ndarray:
    r"""Fourier amplitudes [m] of the transverse motion of the point where a span leaves a polygon.

    Parameters
    ----------
    radius : float
        Pitch radius R [m].
    side_angles : array_like
        Central angles of the sides in one period [rad]: ``[2π/z]`` for a roller chain,
        ``[δ1, δ2]`` for a round link chain (Dolipiński et al., δ1 + δ2 = 2π/z).
    harmonics : int
        Amplitudes returned: of the period's 1st, 2nd, ... harmonic.
    samples : int, optional
        Samples of one period for a discrete transform instead of the integral (the
        amplitudes of the sampled motion; default: the integral in closed form).

    Returns
    -------
    numpy.ndarray
        Amplitudes a_k, k = 1...harmonics [m].

    .. math:: y(\theta) = R\cos(\theta - \theta_c), \ |\theta - \theta_c| \le \delta/2 \text{ on each side}

    .. math:: a_k = \frac{2R}{P}\Bigl|\sum_j e^{-i\omega_k\theta_{c,j}}\,h_j\bigl(
              \operatorname{sinc}\tfrac{(1-\omega_k)h_j}{\pi} + \operatorname{sinc}\tfrac{(1+\omega_k)h_j}{\pi}\bigr)\Bigr|,
              \qquad \omega_k = \frac{2\pi k}{P},\ h_j = \frac{\delta_j}{2}

    Notes
    -----
    The span leaves from the last seated hinge; while a side of central angle δ turns
    through δ, the hinge's distance from the line through the axis parallel to the span
    is R cos φ, φ from −δ/2 to δ/2 (the chordal action without a guide). Its Fourier
    coefficients over the period ``P = Σδ`` are integrated side by side in closed form
    (``∫ cos u cos ωu du`` over ``|u| <= h``; the odd part vanishes); tested against the
    transform of 2²⁰ samples. With ``samples``: sampled uniformly in the wheel angle, then FFT.

    Examples
    --------
    >>> a = polygon_transverse_harmonics(0.069, [2 * np.pi / 17], 2)
    >>> round(float(a[0]) * 1e3, 3)
    0.476

    References
    ----------
    Dolipiński et al. (free entry, transverse throw R(1 − cos(δ1/2))); the chordal action
    of roller chains, e.g. Binder, Roller Chain Drives (1956), ch. 2.
    """
    r = float(check_positive("radius", radius, "m"))
    sides = np.asarray(check_positive("side_angles", side_angles, "rad"), dtype=float).ravel()
    period = sides.sum()
    if samples is None:
        half = 0.5 * sides
        centre = np.cumsum(sides) - half  # (j,)
        omega = 2.0 * np.pi / period * np.arange(1, int(harmonics) + 1)[:, None]  # (k, 1)
        terms = np.exp(-1j * omega * centre) * half * (np.sinc((1.0 - omega) * half / np.pi)
                                                       + np.sinc((1.0 + omega) * half / np.pi))
        return 2.0 * r / period * np.abs(terms.sum(axis=1))
    theta = (np.arange(samples) + 0.5) / samples * period
    edges = np.concatenate([[0.0], np.cumsum(sides)])
    j = np.clip(np.searchsorted(edges, theta, side="right") - 1, 0, sides.size - 1)
    phi = theta - (edges[j] + edges[j + 1]) / 2.0
    y = r * np.cos(phi)
    spec = np.fft.rfft(y) / samples
    return 2.0 * np.abs(spec[1:harmonics + 1])


@finite_guard
def forced_span_response(span: TensionerSpan, frequency: ArrayLike, end_amplitude_1: float = 1.0,
                         end_amplitude_2: float = 0.0, *, damping_ratio: float = DAMPING_RATIO,
                         points: int = 101) -> tuple[np.ndarray, np.ndarray]:
    r"""Steady forced response of the slack span with its tensioner to a motion of its ends.

    Parameters
    ----------
    span : TensionerSpan
        The slack span and its tensioner (coupling model of the span).
    frequency : float or array_like
        Ω [rad/s], > 0.
    end_amplitude_1, end_amplitude_2 : float
        Amplitudes of the motion of the far end of part 1 and of part 2, normal to the
        part [m]; their responses are added in magnitude (the phases are unknown).
    damping_ratio : float
        ζ: loss factor 2ζ on the tension (structural damping; ζ of each mode at resonance).
    points : int
        Points per part where the amplitude is evaluated.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        The largest transverse amplitude along the span [m] and the tensioner's
        amplitude along its axis [m], per frequency.

    .. math:: u = \frac{\hat T_1 g_1 k_1 Y}{\sin(k_1\ell_1)\,G(\Omega)},\quad
              w_1(s) = Y\cos k_1 s + \frac{g_1 u - Y\cos k_1\ell_1}{\sin k_1\ell_1}\sin k_1 s,\quad
              w_2(s) = g_2 u \frac{\sin k_2(\ell_2 - s)}{\sin k_2\ell_2}

    with :math:`\hat T_i = T_i(1 + 2i\zeta)`, :math:`k_i = \Omega\sqrt{q/\hat T_i}` and G the
    frequency function (:func:`~chaindrive.vibration.frequency_function`) with these.

    Notes
    -----
    Exact for the string model of the frequency equation (no modal truncation): the
    separated solutions with the moving end satisfy the tensioner's equation of motion.
    Checked against the planar bead model
    (:func:`chaindrive.vibration.planar.planar_forced_response`). Stationary span.

    Examples
    --------
    >>> s = TensionerSpan(2000.0, 2.6, 0.8, 1.1, 0.3, 0.3, 3.0, 5e4)
    >>> w, u = forced_span_response(s, [1.0, 77.0], 1e-3)
    >>> np.round(w * 1e3, 2)
    array([1.  , 3.51])

    References
    ----------
    the tensioner paper, eqs (1)-(10); docs/vibration.md, §6a.
    """
    om = np.atleast_1d(check_positive("frequency", frequency, "rad/s")).astype(float)
    y1 = float(check_nonnegative("end_amplitude_1", end_amplitude_1, "m"))
    y2 = float(check_nonnegative("end_amplitude_2", end_amplitude_2, "m"))
    zeta = float(check_range("damping_ratio", damping_ratio, 0.0, 1.0, low_inclusive=False))
    from ..limits import check_size

    n = check_size("points", points, 10_000, minimum=2)
    w_max, u_amp = _span_response(span, om, y1, y2, zeta, n, np.array([float(span.mass)]),
                                  np.array([float(span.stiffness)]))
    return w_max[0], u_amp[0]


def _span_response(span: TensionerSpan, om: np.ndarray, y1: Any, y2: Any, zeta: float, n: int,
                   mass: np.ndarray, stiffness: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`forced_span_response` for K tensioners at once: ``mass``, ``stiffness`` of shape
    (K,) [kg], [N/m]; returns the largest span amplitude and the tensioner's, shape (K, len(om)).
    ``y1``, ``y2``: the end amplitudes [m], or one per frequency (arrays like ``om``)."""
    g = COUPLING_MODELS.get(span.model)
    parts = [(span.length_1, span.angle_1), (span.length_2, span.angle_2)]
    t_hat = [span.tension / np.cos(b) * (1 + 2j * zeta) for _, b in parts]
    k = [om * np.sqrt(span.mass_per_length / t) for t in t_hat]
    gg = [float(g(np.asarray(b))) for _, b in parts]
    ell = [p[0] for p in parts]
    G = (sum(t_hat[i] * gg[i] ** 2 * k[i] / np.tan(k[i] * ell[i]) for i in range(2))[None, :]
         + stiffness[:, None] - mass[:, None] * om[None, :] ** 2)            # (K, F)
    s_unit = np.linspace(0.0, 1.0, n)
    w_max = np.zeros(G.shape)
    u_amp = np.zeros(G.shape)
    # the shapes along the span of each distinct frequency once (a frequency asked for again, the
    # quasi-static one of every excitation: its rows gathered, the same numbers)
    distinct, again = np.unique(om, return_inverse=True) if om.ndim == 1 else (om, None)
    repeated = distinct.size < om.size
    kd = [distinct * np.sqrt(span.mass_per_length / t) for t in t_hat] if repeated else k

    def rows(x: np.ndarray) -> np.ndarray:
        return x[again] if repeated else x

    for a, y in ((0, y1), (1, y2)):  # the excited part a, the other b
        if np.all(np.asarray(y) == 0.0):
            continue
        b = 1 - a
        # y: one amplitude, or one per frequency (F,) (the same products element by element)
        yc = y if np.ndim(y) == 0 else np.asarray(y, dtype=float)[:, None]
        u = (t_hat[a] * gg[a] * k[a] * y / np.sin(k[a] * ell[a]))[None, :] / G          # (K, F)
        sa = s_unit * ell[a]
        ka = k[a][:, None]                                                             # (F, 1)
        kda = kd[a][:, None]
        # cos and sin of the complex k s from one exponential (cos z = (e^iz + e^-iz)/2, sin z =
        # (e^iz - e^-iz)/2i; within a few roundings of np.cos and np.sin at these damped k)
        turn = np.exp(1j * (kda * sa))
        back = 1.0 / turn
        wa = (yc * rows(0.5 * (turn + back)))[None] + ((gg[a] * u[..., None] - (yc * np.cos(ka * ell[a])))
                                                       / np.sin(ka * ell[a])) * rows(-0.5j * (turn - back))[None]
        sb = s_unit * ell[b]
        kdb = kd[b][:, None]
        wb = gg[b] * u[..., None] * rows(np.sin(kdb * (ell[b] - sb)) / np.sin(kdb * ell[b]))[None]
        w_max += np.maximum(np.abs(wa).max(axis=-1), np.abs(wb).max(axis=-1))
        u_amp += np.abs(u)
    return w_max, u_amp


@dataclasses.dataclass(frozen=True)
class ExcitationResponse(Result):
    """One excitation of the slack span: its frequency, amplitude, source and the response.

    Attributes
    ----------
    name : str
        As in :func:`~chaindrive.vibration.excitation_multipliers`.
    frequency : float
        ω_j [rad/s].
    end_amplitude : float
        Transverse amplitude of the span's ends from this source [m].
    response : float
        Largest transverse amplitude along the span [m] (both ends excited, added).
    tensioner_amplitude : float
        The tensioner's amplitude along its axis [m].
    amplification : float
        response / its quasi-static value (Ω → 0).
    criterion : str
        ``"response"``: judged by its amplification ≤ :data:`AMPLIFICATION_LIMIT` (every
        excitation; the tensioner paper's band 0.7 ≤ P/ω ≤ 1.4 is information beside it).
    passed : bool or None
        amplification ≤ :data:`AMPLIFICATION_LIMIT` (None when the excitation has no amplitude).
    source : str
        Physical origin and the source of its amplitude.
    """

    name: str
    frequency: float = quantity("rad/s", display="Hz")
    end_amplitude: float = quantity("m", display="mm")
    response: float = quantity("m", display="mm")
    tensioner_amplitude: float = quantity("m", display="mm")
    amplification: float = quantity("1")
    criterion: str = "response"
    passed: bool | None = None
    source: str = ""


#: Why each excitation exists and where its amplitude comes from.
_SOURCES = {
    "driving sprocket": "eccentricity of the driving wheel at its speed (tensioner paper); amplitude: "
                        "radial run-out tolerance, ISO 606:2015, 5.7",
    "driven sprocket": "eccentricity of the driven wheel at its speed (tensioner paper); amplitude: "
                       "radial run-out tolerance, ISO 606:2015, 5.7",
    "unequal links (inner/outer)": "inner and outer links of unequal pitch, period two pitches (tensioner "
                                   "paper); amplitude: pitch difference within the ISO 606:2015 length "
                                   "tolerance, 3.4.4",
    "meshing": "chordal action of the pitch polygon, period one pitch; amplitude: transverse throw of the "
               "span end (Fourier fundamental)",
    "link pair (t ± d)": "unequal chords t + d, t − d of a round link chain on a pocket wheel, the "
                         "period of its bi-regular polygon (tensioner paper; Dolipiński et al., eq. 6); "
                         "amplitude: Fourier fundamental of the transverse throw",
    "link passing": "chordal action of the round link chain, each link (2 z1 ω1); amplitude: transverse "
                    "throw of the span end (Fourier component)",
}


@finite_guard
def span_excitations(span: TensionerSpan, speed: float, *, ratio: float, teeth_driving: int,
                     teeth_driven: int, radius_driving: float, radius_driven: float, pitch: float,
                     bar_diameter: float | None = None, damping_ratio: float = DAMPING_RATIO
                     ) -> tuple[ExcitationResponse, ...]:
    r"""Every excitation of a drive's slack span with its amplitude and the forced response.

    Parameters
    ----------
    span : TensionerSpan
        The slack span with its tensioner.
    speed : float
        Driving wheel speed ω1 [rad/s].
    ratio : float
        u = ω1/ω2.
    teeth_driving, teeth_driven : int
        z1, z2.
    radius_driving, radius_driven : float
        Pitch radii [m].
    pitch : float
        Chain pitch t [m].
    bar_diameter : float, optional
        d [m] of a round link chain (None: roller chain).
    damping_ratio : float
        ζ (default :data:`DAMPING_RATIO`).

    Returns
    -------
    tuple of ExcitationResponse
        One per excitation of :func:`~chaindrive.vibration.excitation_multipliers` (with
        the round link chain's harmonic).

    .. math:: \text{response}_j = \max_s |w(s)|\ \text{at}\ \Omega = k_j\omega_1

    Notes
    -----
    Both ends of the span are excited with the same amplitude (the smaller wheel's
    polygon, the wheel's own run-out at its own speed, the unequal links on the smaller
    wheel) and their responses added in magnitude: an upper estimate. Every excitation (the
    paper's three and the polygon, ``meshing``, ``link passing``, which the paper does not
    name) passes when its amplification is at most :data:`AMPLIFICATION_LIMIT`, the
    amplification of one undamped mode at the paper's band edge P/ω = 1.4.

    Examples
    --------
    >>> s = TensionerSpan(2000.0, 2.6, 0.8, 1.1, 0.3, 0.3, 3.0, 5e4)
    >>> rows = span_excitations(s, 10.0, ratio=2.0, teeth_driving=17, teeth_driven=34,
    ...                         radius_driving=0.069, radius_driven=0.1376, pitch=0.0254)
    >>> [r.name for r in rows]
    ['driving sprocket', 'driven sprocket', 'unequal links (inner/outer)', 'meshing']

    References
    ----------
    the tensioner paper; ISO 606:2015, 3.4.4 and 5.7; Dolipiński et al., eq. (6).
    """
    w1 = float(check_positive("speed", speed, "rad/s"))
    link = bar_diameter is not None
    ks = excitation_multipliers(ratio, teeth_driving, link_chain=link, polygon=True)
    z_small, r_small = min((teeth_driving, radius_driving), (teeth_driven, radius_driven))
    if bar_diameter is not None:
        d = float(check_positive("bar_diameter", bar_diameter, "m"))
        rad = r_small
        d1 = 2 * np.arcsin(min(1.0, (pitch + d) / (2 * rad)))
        polygon = polygon_transverse_harmonics(rad, [d1, 2 * np.pi / z_small - d1], 2)
    else:
        polygon = polygon_transverse_harmonics(r_small, [2 * np.pi / z_small], 1)
    amplitude = {
        "driving sprocket": float(runout_tolerance(2 * radius_driving)),
        "driven sprocket": float(runout_tolerance(2 * radius_driven)),
        "unequal links (inner/outer)": 0.0 if link else unequal_link_amplitude(pitch, z_small),
        "meshing": float(polygon[0]),
        "link pair (t ± d)": float(polygon[0]),
        "link passing": float(polygon[1]) if link else 0.0,
    }
    responses = _responses(span, w1, ks, amplitude, damping_ratio)
    rows = []
    for name, k in ks.items():
        a = amplitude[name]
        w, u = responses[name]
        amp = float(w[0] / w[1]) if a > 0 else 0.0
        rows.append(ExcitationResponse(name=name, frequency=k * w1, end_amplitude=a, response=float(w[0]),
                                       tensioner_amplitude=float(u[0]), amplification=amp,
                                       passed=bool(amp <= AMPLIFICATION_LIMIT) if a > 0 else None,
                                       source=_SOURCES[name]))
    return tuple(rows)


def _responses(span: TensionerSpan, w1: float, ks: dict[str, float], amplitude: dict[str, float],
               damping_ratio: float) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """``forced_span_response(span, [k w1, 1e-6 w1], a, a)`` of every excitation, those with an
    amplitude in one call (each frequency with its own amplitude: the same numbers); an
    excitation without amplitude has no response. Where a response is not finite, each is
    asked for alone (which says why)."""
    live = [name for name in ks if amplitude[name] != 0.0]
    out = {name: (np.zeros(2), np.zeros(2)) for name in ks if name not in live}
    if not live:
        return out
    om = np.array([ks[name] * w1 for name in live] + [1e-6 * w1 for _ in live])
    y = np.array([amplitude[name] for name in live] * 2)
    if np.all(om > 0) and np.all(y >= 0) and 0.0 < damping_ratio < 1.0:
        w, u = _span_response(span, om, y, y, float(damping_ratio), 101, np.array([float(span.mass)]),
                              np.array([float(span.stiffness)]))
        if np.all(np.isfinite(w)) and np.all(np.isfinite(u)):
            m = len(live)
            for i, name in enumerate(live):
                out[name] = (w[0, [i, m + i]], u[0, [i, m + i]])
            return out
    for name in live:
        a = amplitude[name]
        out[name] = forced_span_response(span, np.array([ks[name] * w1, 1e-6 * w1]), a, a,
                                         damping_ratio=damping_ratio)
    return out
