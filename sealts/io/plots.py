"""PNG plots of film profiles and time series (matplotlib, Agg backend)."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def plot_profiles(profiles, path):
    """Film thickness (um), pressure and shear (MPa) along y for each output time."""
    has_asp = "p_asperity" in profiles[0][1]
    fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    for t, pr in profiles:
        lab = f"t = {t:.4g} s"
        ax[0].plot(pr["y"], np.asarray(pr["h"]) * 1e3, label=lab)
        ax[1].plot(pr["y"], pr["p"], label=lab)
        if has_asp:
            ax[1].plot(pr["y"], pr["p_asperity"], "--", label=f"asperity, {lab}")
        ax[2].plot(pr["y"], pr["tau"], label=lab)
    ax[0].set_ylabel("film thickness h [um]")
    ax[1].set_ylabel("pressure p [MPa]")
    ax[2].set_ylabel("fluid shear tau [MPa]")
    ax[2].set_xlabel("axial position y [mm]")
    for a in ax:
        a.grid(alpha=0.3)
    if len(profiles) <= 8:
        ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_series(rows, path):
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
