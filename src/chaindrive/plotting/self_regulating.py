"""Plot of a self-regulating drive: slack tension, ψ, centre distance and sag over load and wear."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # matplotlib is an optional extra
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..self_regulating import SelfRegulatingDriveResult

__all__ = ["self_regulating_plot"]


def self_regulating_plot(result: SelfRegulatingDriveResult, *, ax: Sequence[Axes] | None = None) -> Figure:
    """Slack tension against load, ψ and centre distance against wear, sag at the rated load.

    Parameters
    ----------
    result : chaindrive.self_regulating.SelfRegulatingDriveResult
    ax : sequence of four or six matplotlib Axes, optional
        A new figure if omitted: 2 × 2, or 2 × 3 when the result has the carrier's
        natural frequency.

    Returns
    -------
    matplotlib.figure.Figure

    Notes
    -----
    Lines are the closed forms; open markers the full numerical equilibrium when the
    result has it. Panels: (1) slack tension ``S2`` against the load for each wear
    elongation; (2) ψ and ``S2/F_t`` at the rated load against the elongation, with the
    rational value; (3) centre distance against the elongation for the smallest, the
    rated and the largest load; (4) slack-span sag ratio at the rated load with the
    allowance; with the carrier frequency, (5) the carrier's natural frequency against
    the load with the forbidden bands 0.7…1.4 ω_j of the exciting frequencies (the
    tensioner paper) and (6) the shaft load on the carrier wheel per unit effective pull.

    Examples
    --------
    >>> from chaindrive.self_regulating import example_drive
    >>> r = example_drive()  # self_regulating_drive's example, closed forms only
    >>> len(self_regulating_plot(r).axes)  # the carrier's weight gives its frequency panel
    6
    """
    import matplotlib.pyplot as plt

    freq = result.carrier_frequency
    if ax is None:
        if freq is None:
            fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
        else:
            fig, axes = plt.subplots(2, 3, figsize=(15.5, 7.5))
        axes = axes.ravel()
        if freq is not None:  # reading order: S2, ψ, frequency / a, sag, shaft load
            axes = [axes[0], axes[1], axes[3], axes[4], axes[2], axes[5]]
    else:
        axes = list(ax)
        if len(axes) not in (4, 6):
            from ..errors import InputError

            raise InputError(f"ax must be a sequence of 4 or 6 Axes, got {len(axes)}")
        fig = axes[0].figure
    lam = np.asarray(result.load_factor)
    e = np.asarray(result.elongation)
    i1 = int(np.argmin(np.abs(lam - 1.0)))
    num = result.numerical_slack_tension is not None
    colours = plt.get_cmap("viridis")(np.linspace(0.0, 0.85, e.size))

    a = axes[0]
    for j, c in enumerate(colours):
        a.plot(lam, result.slack_tension[:, j] / 1e3, color=c, lw=1.6,
               label=f"e = {100 * e[j]:.2g} %")
        if result.numerical_slack_tension is not None:
            a.plot(lam, result.numerical_slack_tension[:, j] / 1e3, "o", mfc="none", color=c, ms=5)
    a.axhline(result.slack_tension_rational / 1e3, color="0.4", ls=":", lw=1,
              label="S2* (sag allowance at rated load)")
    a.set_xlabel("load: torque / nominal torque [-]")
    a.set_ylabel("slack tension S2 [kN]")
    a.set_title("Slack tension against load" + (" (○ numerical equilibrium)" if num else ""))
    a.legend(fontsize=8)

    a = axes[1]
    a.plot(100 * e, result.psi[i1], "-o", color="tab:blue", label="ψ = ∂S2/∂F_t")
    a.plot(100 * e, result.rated_ratio, "-s", color="tab:orange", label="S2/F_t at rated load")
    a.axhline(result.psi_rational, color="0.3", ls="--", lw=1, label=f"rational ψ* = {result.psi_rational:.3g}")
    a.set_xlabel("wear elongation e [%]")
    a.set_ylabel("coefficient [-]")
    a.set_title("Regulation coefficient ψ over the wear range")
    a.legend(fontsize=8)

    a = axes[2]
    for i, style in ((0, ":"), (i1, "-"), (lam.size - 1, "--")):
        a.plot(100 * e, result.centre_distance[i] * 1e3, style, color="tab:green",
               label=f"load {lam[i]:.2g}")
        if result.numerical_centre_distance is not None:
            a.plot(100 * e, result.numerical_centre_distance[i] * 1e3, "o", mfc="none",
                   color="tab:green", ms=5)
    a.set_xlabel("wear elongation e [%]")
    a.set_ylabel("centre distance a [mm]")
    unit = "rad" if result.coordinate_unit == "rad" else "mm"
    travel = result.carrier_travel * (1.0 if unit == "rad" else 1e3)
    a.set_title(f"Centre distance (carrier travel {travel:.3g} {unit})")
    a.legend(fontsize=8)

    a = axes[3]
    a.plot(100 * e, 100 * result.sag_ratio[i1], "-o", color="tab:red", label="slack span, rated load")
    a.plot(100 * e, 100 * result.sag_ratio[0], ":", color="tab:red", label=f"load {lam[0]:.2g}")
    a.axhline(100 * result.sag_allowance, color="0.3", ls="--", lw=1, label="allowance")
    a.set_xlabel("wear elongation e [%]")
    a.set_ylabel("sag / chord [%]")
    a.set_title("Slack-span sag")
    a.legend(fontsize=8)

    if len(axes) == 6:
        a = axes[4]
        if freq is not None:
            for j, c in enumerate(colours):
                a.plot(lam, freq[:, j], "-o", ms=3, color=c, label=f"e = {100 * e[j]:.2g} %")
            for k, (name, w) in enumerate((result.excitations or {}).items()):
                a.axhspan(0.7 * w, 1.4 * w, color=f"C{k + 1}", alpha=0.15,
                          label=f"0.7…1.4 × {name} ({w:.4g} rad/s)")
            a.set_yscale("log")
            a.legend(fontsize=7)
            ok = result.resonance_margin is None or bool(np.min(result.resonance_margin) > 0)
            a.set_title("Carrier natural frequency" + ("" if ok else " (in a forbidden band)"))
        a.set_xlabel("load: torque / nominal torque [-]")
        a.set_ylabel("frequency [rad/s]")
        a = axes[5]
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = result.shaft_load[1:] / result.effective_pull[1:]
        for j, c in enumerate(colours):
            a.plot(lam[1:], ratio[:, j], color=c, label=f"e = {100 * e[j]:.2g} %")
        a.set_xlabel("load: torque / nominal torque [-]")
        a.set_ylabel("shaft load / F_t [-]")
        a.set_title("Shaft load on the carrier wheel")
        a.legend(fontsize=8)
    fig.suptitle(f"Self-regulating drive: wheel {result.wheel!r} on a {result.kind} carrier "
                 f"({result.links} links)", fontsize=11)
    fig.tight_layout()
    return fig
