"""PNG plots of film profiles and time series (matplotlib, Agg backend)."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def plot_profiles(profiles, path):
    """Film thickness (um), pressures and shear (MPa) along y for each output time.

    Plots whichever of p, p_asperity, p_contact (pressures) and tau, tau_solid (shear) the
    profiles carry."""
    first = profiles[0][1]
    pressures = [k for k in ("p", "p_asperity", "p_contact") if k in first]
    shears = [k for k in ("tau", "tau_solid") if k in first]
    rows = 2 + bool(shears)
    fig, ax = plt.subplots(rows, 1, figsize=(7, 2.7 * rows + 0.5), sharex=True)
    for t, pr in profiles:
        lab = f"t = {t:.4g}"
        ax[0].plot(pr["y"], np.asarray(pr["h"]) * 1e3, label=lab)
        for k, style in zip(pressures, ("-", "--", "-")):
            ax[1].plot(pr["y"], pr[k], style, label=f"{k}, {lab}")
        for k, style in zip(shears, ("-", "--")):
            ax[2].plot(pr["y"], pr[k], style, label=f"{k}, {lab}")
    h_all = np.concatenate([np.asarray(pr["h"]) for _, pr in profiles])
    if h_all.min() > 0.0 and h_all.max() > 100.0 * h_all.min():
        ax[0].set_yscale("log")      # a seal's film: um in the contact, mm in the wedges
    ax[0].set_ylabel("gap h [um]")
    ax[1].set_ylabel("pressure [MPa]")
    if shears:
        ax[2].set_ylabel("shear stress [MPa]")
    ax[-1].set_xlabel("axial position y [mm]")
    for a in ax:
        a.grid(alpha=0.3)
    if len(profiles) * len(pressures) <= 8:
        ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_series(rows, path):
    if "rod_force" in rows[0]:
        return plot_hold_series(rows, path)
    t = np.array([r["t"] for r in rows])
    fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    ax[0].plot(t, [r["Q_in"] for r in rows], label="Q_in")
    ax[0].plot(t, [r["Q_out"] for r in rows], label="Q_out")
    ax[0].set_ylabel("flow [mm^3/s]")
    ax[0].legend()
    if "V_in" in rows[0]:
        ax[1].plot(t, [r["V_in"] for r in rows], label="V_in")
        ax[1].plot(t, [r["V_out"] for r in rows], label="V_out")
        ax[1].legend()
    ax[1].set_ylabel("volume [mm^3]")
    ax[2].semilogy(t, [max(r["dt"], 1e-300) for r in rows], ".-")
    ax[2].set_ylabel("time step [s]")
    ax[2].set_xlabel("time t [s]")
    for a in ax:
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_hold_series(rows, path):
    """A seal's viscoelastic hold over log time: rod force, peak contact pressure, step."""
    t = np.array([r["t"] for r in rows])
    keep = t > 0
    fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    ax[0].semilogx(t[keep], np.array([r["rod_force"] for r in rows])[keep], ".-")
    ax[0].set_ylabel("rod contact force [N]")
    ax[1].semilogx(t[keep], np.array([r["p_contact_max"] for r in rows])[keep], ".-")
    ax[1].set_ylabel("peak contact pressure [MPa]")
    ax[2].loglog(t[keep], np.array([max(r["dt"], 1e-300) for r in rows])[keep], ".-")
    ax[2].set_ylabel("time step [s]")
    ax[2].set_xlabel("time in the hold t [s]")
    for a in ax:
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
