"""Layer 7, figures of the contact analysis (matplotlib, the ``plot`` extra): the transmission
error and mesh stiffness over a mesh cycle, the contact pattern (Hertzian pressure over the
flank), and the Harris map (transmission error peak to peak over tip relief and load).

Each function takes the result object (:class:`gears.contact.result.Contact` or
:class:`gears.contact.result.HarrisMap`) and returns a matplotlib figure; ``ax`` draws into an
existing axes (the stiffness panel of :func:`te_figure` then goes on a twin axis).
"""

from __future__ import annotations

from gears.files import pyplot

__all__ = ["harris_figure", "pattern_figure", "te_figure"]


def te_figure(contact, ax=None):
    """Loaded and unloaded transmission error (um, left) and mesh stiffness (N/(mm um),
    right) over one mesh cycle, against gear 1's rotation (degrees)."""
    plt = pyplot()
    fig, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(7, 4))
    angle = contact.angle
    ax.plot(angle, contact.transmission_error, color="C0", lw=1.6, label="loaded TE")
    ax.plot(angle, contact.unloaded_transmission_error, color="C0", ls="--", lw=1,
            label="unloaded TE")  # fmt: skip
    ax.set_xlabel("gear 1 rotation in the mesh cycle (deg)")
    ax.set_ylabel("transmission error (um on the line of action)")
    ax.set_title(
        f"T1 = {contact.torque:g} N m: peak to peak {contact.peak_to_peak:.2f} um, "
        f"mean stiffness {contact.mean_mesh_stiffness:.2f} N/(mm um)",
        fontsize=9,
    )
    right = ax.twinx()
    right.plot(angle, contact.mesh_stiffness, color="C1", lw=1, label="mesh stiffness")
    right.set_ylabel("mesh stiffness (N/(mm um))", color="C1")
    lines = ax.get_lines() + right.get_lines()
    ax.legend(lines, [ln.get_label() for ln in lines], fontsize=8, loc="lower right")
    fig.tight_layout()
    return fig


def pattern_figure(contact, ax=None):
    """The contact pattern: the largest Hertzian pressure p_0 (MPa) over gear 1's flank in a
    mesh cycle, face width across, roll position on the line of action up."""
    plt = pyplot()
    fig, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(6, 4.5))
    face, roll, p = contact.face, contact.profile, contact.pressure
    mesh = ax.pcolormesh(face, roll, p.T, shading="nearest", cmap="inferno")
    fig.colorbar(mesh, ax=ax, label="Hertzian pressure p0 (MPa)")
    ax.set_xlabel("face position (mm from the centre)")
    ax.set_ylabel("roll position on the line of action (mm from N1)")
    ax.set_title(f"K_Hbeta = {contact.K_Hbeta:.3f}, K_Halpha = {contact.K_Halpha:.3f}", fontsize=9)
    fig.tight_layout()
    return fig


def harris_figure(harris_map, ax=None):
    """The Harris map: transmission error peak to peak (um, colour and contours) over tip
    relief (um) and torque (N m), with each torque's best relief."""
    plt = pyplot()
    fig, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(6, 4.5))
    r = harris_map.reliefs * 1000.0
    t = harris_map.torques
    p2p = harris_map.peak_to_peak
    if r.size > 1 and t.size > 1:
        filled = ax.contourf(r, t, p2p.T, levels=20, cmap="viridis")
        fig.colorbar(filled, ax=ax, label="TE peak to peak (um)")
        ax.contour(r, t, p2p.T, levels=10, colors="w", linewidths=0.4)
        ax.plot(harris_map.best_relief() * 1000.0, t, "r.-", lw=1, label="best relief")
        ax.set_ylabel("torque on gear 1 (N m)")
        ax.legend(fontsize=8, loc="upper left")
    else:
        for j, torque in enumerate(t):
            ax.plot(r, p2p[:, j], label=f"{torque:g} N m")
        ax.set_ylabel("TE peak to peak (um)")
        ax.legend(fontsize=8)
    ax.set_xlabel(f"tip relief on both gears (um, over {harris_map.relief_length:.2f} mm of roll)")
    fig.tight_layout()
    return fig
