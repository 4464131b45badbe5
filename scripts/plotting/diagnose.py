"""`gearloss diagnose --residuals` pictures: residuals (recorded - model) over speed, coloured by
torque, before and after the fit, and recorded against model; the oil temperature beside the
loss when the campaign recorded it."""
import numpy as np

from . import labels
from .data import PlotError


def plot_diagnose(fig, table, meta, opts):
    if opts.levels is not None:
        raise PlotError("--levels applies to the map and compare pictures, not to diagnose")
    n, tq = table.number("speed_in_rpm"), table.number("torque_in_Nm")
    has_T = table.has("oil_temp_C") and np.isfinite(table.number("oil_temp_C")).any()
    if has_T:
        table.require(["oil_temp_model_before_C", "oil_temp_model_after_C"], "diagnose")
    ncol = 2 if has_T else 1
    fig.set_size_inches(12 if has_T else 6.5, 8.5)
    ax = fig.subplots(2, ncol, squeeze=False)

    def column(c, rec, before, after, residual_label, model_label, recorded_label):
        sc = ax[0][c].scatter(n, rec - before, c=tq, marker="o", label="before", cmap="viridis")
        ax[0][c].scatter(n, rec - after, c=tq, marker="x", label="after", cmap="viridis")
        ax[0][c].axhline(0, color="grey", lw=0.8)
        ax[0][c].set_xlabel("input speed [rpm]")
        ax[0][c].set_ylabel(residual_label)
        ax[0][c].legend()
        vals = np.concatenate([rec, before, after])
        vals = vals[np.isfinite(vals)]
        if vals.size:
            ax[1][c].plot([vals.min(), vals.max()], [vals.min(), vals.max()], color="grey", lw=0.8)
        ax[1][c].scatter(before, rec, marker="o", label="before")
        ax[1][c].scatter(after, rec, marker="x", label="after")
        ax[1][c].set_xlabel(model_label)
        ax[1][c].set_ylabel(recorded_label)
        ax[1][c].legend()
        return sc

    sc = column(0, table.number("P_loss_W"), table.number("P_model_before_W"), table.number("P_model_after_W"),
                "loss residual, recorded - model [W]", "model loss [W]", "recorded loss [W]")
    fig.colorbar(sc, ax=ax[0][0], label="input torque [N m]")
    if has_T:
        column(1, table.number("oil_temp_C"), table.number("oil_temp_model_before_C"),
               table.number("oil_temp_model_after_C"), "oil temperature residual [K]",
               "model oil temperature [degC]", "recorded oil temperature [degC]")
    oil = ", ".join(labels.oil_names(meta))
    title = labels.figure_title(opts.title, f"{labels.case_text(meta, table.path)}: diagnosis residuals, "
                                            "before and after the fit",
                                labels.join(f"oil {oil}" if oil else "", f"{len(table)} recorded points"))
    labels.set_title(fig, title)
    return {"title": title, "panels": []}
