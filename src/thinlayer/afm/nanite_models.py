r"""thinlayer's any-thickness laws as nanite fit models (issue 25 item 1): nanite scripts and PyJibe list them.

nanite's documented custom-model interface (nanite docs, "Writing model functions") is a module with
``get_parameter_defaults()`` (lmfit ``Parameters``), the model function ``model_func(delta, *parameter_keys)``,
``model_doc``, ``model_key``, ``model_name``, ``parameter_keys``/``names``/``units`` and ``valid_axes_x =
["tip position"]`` (negative into the sample: the indentation is ``contact_point - delta``), registered with
``nanite.model.register_model(module)``.  :func:`model_module` builds one such module per (tip, base);
:func:`register` registers them all::

    import nanite
    from thinlayer.afm.nanite_models import register
    register()                       # thinlayer_para_bonded, thinlayer_cone_frictionless, ...
    idnt.fit_model(model_key="thinlayer_para_bonded", params_initial=params)

PyJibe loads model *files* (Preferences, through ``nanite.model.load_model_from_file``): write one with
``thinlayer codegen nanite --tip sphere --base bonded --nu 0.5 --out DIR`` (standalone: numpy only) and load it.

The models (parameters ``E`` [Pa], the tip's size, ``nu`` (fixed), ``H`` [m] (fixed by default; free with
``params["H"].vary = True``; ``inf``: the half-space), ``contact_point`` [m], ``baseline`` [N]):

========================  ==========================================================================================
``thinlayer_para_<base>``  paraboloid of radius ``R``: (T.7), ``thinlayer.contact.any_thickness.force_any_thickness``
                           (every ``chi = sqrt(R delta)/H``; estimate <= 2.1e-4 against the direct solver); ``H =
                           inf``: Hertz, ``(4/3) E/(1 - nu^2) R^{1/2} delta^{3/2}``, nanite's ``hertz_para``
``thinlayer_cone_<base>``  cone of half-angle ``alpha`` [deg]: (T.9), ``contact.any_thickness_tips.cone_law``
                           (bonded ``0.3 <= nu <= 1/2`` or frictionless; ``chi = c_0/H <= chi_max`` ~ 21, beyond it
                           the law refuses: the thin layer, give thinlayer.fit's tip-law or direct model); ``H =
                           inf``: Sneddon, ``(2/pi) tan(alpha) E/(1 - nu^2) delta^2``, nanite's ``hertz_cone``
``thinlayer_flat_<base>``  flat-ended cylinder of radius ``a``: ``P = 2 E a delta kappa(a/H)/(1 - nu^2)`` (F.1),
                           :func:`thinlayer.contact.flat_punch.flat_punch_stiffness` (exact); ``H = inf``: ``kappa =
                           1`` (Sneddon's flat punch; nanite has no flat-punch model)
``thinlayer_pyr3s_<base>`` regular pyramid, 3 or 4 sides, face angle ``alpha`` [deg] (axis to face, as nanite's
``thinlayer_pyr4s_<base>`` ``hertz_pyr3s``): ``P = (K/2) E/(1 - nu^2) tan(alpha) delta^2 Pi(chi)``, ``chi = delta
                           tan(alpha)/H`` (T.11)-(T.13), :func:`thinlayer.contact.any_thickness_pyramids.pyramid_law`
                           (the series (T.12) below chi = 0.05, a table of solve_2d solutions to chi = 10; bonded
                           ``0.3 <= nu <= 1/2`` or frictionless; beyond chi = 10 the law refuses: the thin layer);
                           ``H = inf``: the half-space, K = 1.764825 (3 sides), 1.475233 (4 sides) from solve_2d
========================  ==========================================================================================

The pyramid's half-space constant is not nanite's.  nanite's ``hertz_pyr3s`` (nanite 4.2.3, a secondary source: its
code ``F = 0.8887 tan(alpha) E/(1 - nu^2) delta^2``; its docstring prints 0.887 and cites Bilodeau (1992), an
approximation for small face angles) is 0.71 % stiffer than the converged direct solution (T.13), ``K/2 =
0.882412 +- 1.8e-5``, so E fitted with the thinlayer model is ``0.8887/0.882412 = 1.00712`` times nanite's on the same
curve (tested on real curves).  nanite 4.2.3 has no four-sided pyramid; Bilodeau's four-sided constant 0.7453 (as
quoted in the AFM literature, not checked against the paper here) is 1.04 % above ``K/2 = 0.737617``.

Viscoelastic models (issue 27 item 4), ``thinlayer_<material>_<tip>_<base>`` for every tip and base above, built by
:func:`visco_model_module` and registered by :func:`register` beside the elastic family: the **approach** of an
indentation at **constant speed** (parameter ``speed`` [m/s], fixed), so that ``delta = v t`` from the contact point on
and Lee-Radok's integral is a function of the tip position (:func:`visco_force`):

===============================  ===================================================================================
``thinlayer_sls_<tip>_<base>``   standard linear solid: ``E0`` (instantaneous), ``E_inf`` (relaxed) [Pa], ``tau`` [s]
``thinlayer_powerlaw_<t>_<b>``   ``E(t) = E0 (t/t0)^(-exponent)``: ``E0`` [Pa], ``exponent``, ``t0`` [s] (fixed, 1 s)
===============================  ===================================================================================

then ``speed``, the tip's size, ``nu``, ``H`` (fixed or free, ``inf``: the half-space), ``contact_point``,
``baseline``.  Not for a retraction (the contact shrinks: Ting's method, :func:`thinlayer.fit_viscoelastic` with
``contact_point=True``) nor for a speed that changes during the approach.  ``E0 = E_inf`` is the elastic model with
``E = E_inf`` (to rounding); against the closed forms on the half-space the error is below 1e-6 of the largest force
(tests/afm/test_nanite_visco.py).

Not provided: the exact sphere at finite thickness (the paraboloid is the sphere to ``delta/(10 R)`` in force,
:mod:`thinlayer.contact.guards`).  A force outside a law's table is refused (one line), never extrapolated.
"""
from __future__ import annotations

import math
import types
from functools import lru_cache
from typing import Any

import numpy as np

__all__ = ["BASES", "TIPS", "VISCO_MATERIALS", "model_keys", "model_module", "paraboloid_force", "cone_force",
           "flat_force", "pyramid_force", "register", "visco_force", "visco_model_keys", "visco_model_module"]

#: the tips: key -> (size parameter, its name, unit, default value)
TIPS = {"para": ("R", "Tip Radius", "m", 10e-6), "cone": ("alpha", "Half Cone Angle", "°", 25.0),
        "flat": ("a", "Punch Radius", "m", 10e-6), "pyr3s": ("alpha", "Face Angle", "°", 25.0),
        "pyr4s": ("alpha", "Face Angle", "°", 25.0)}
BASES = ("bonded", "frictionless")
_WORDS = {"para": "paraboloidal indenter", "cone": "conical indenter", "flat": "flat cylindrical punch",
          "pyr3s": "pyramidal indenter, three-sided", "pyr4s": "pyramidal indenter, four-sided"}


def paraboloid_force(indentation: Any, E: float, R: float, nu: float, H: float, base: str = "bonded") -> np.ndarray:
    """Force of the paraboloid ``R`` at ``indentation`` (zero where ``<= 0``) on a layer ``H`` (``inf``: Hertz)."""
    ind = np.asarray(indentation, dtype=float)
    if math.isinf(H):  # Hertz, written as nanite's hertz_para writes it (the same floating-point operations)
        pos = ind > 0
        bb = np.zeros_like(ind)
        bb[pos] = ind[pos] ** (3 / 2)
        return 4 / 3 * E / (1 - nu ** 2) * np.sqrt(R) * bb
    from ..contact.any_thickness import force_any_thickness

    return E * force_any_thickness(ind, R, H, E=1.0, nu=nu, base=base)  # linear in E: E = 0 is a force of 0


def cone_force(indentation: Any, E: float, alpha: float, nu: float, H: float, base: str = "bonded") -> np.ndarray:
    """Force of the cone of half-angle ``alpha`` (degrees) at ``indentation`` on a layer ``H`` (``inf``: Sneddon)."""
    ind = np.asarray(indentation, dtype=float)
    pos = ind > 0
    bb = np.zeros_like(ind)
    bb[pos] = ind[pos] ** 2
    tan = np.tan(alpha * math.pi / 180)
    P0 = 2 * tan / math.pi * E / (1 - nu ** 2) * bb  # Sneddon (T.9), as nanite's hertz_cone writes it
    if math.isinf(H) or not pos.any():
        return P0
    chi = 2 / math.pi * ind[pos] * tan / H  # c_0/H, c_0 = (2/pi) delta tan(alpha)
    ratio = np.ones_like(ind)
    ratio[pos] = _cone_law(float(nu), base).ratios(chi)[0]
    return P0 * ratio


def pyramid_force(indentation: Any, E: float, alpha: float, nu: float, H: float, base: str = "bonded",
                  sides: int = 4) -> np.ndarray:
    """Force of the regular pyramid (``sides`` = 3 or 4) of face angle ``alpha`` (degrees, axis to face) at
    ``indentation`` on a layer ``H`` (``inf``: the half-space, ``P = (K/2) E/(1 - nu^2) tan(alpha) delta^2`` (T.11),
    K of (T.13)).
    """
    from ..asymptotics.pyramid_thick import HALF_SPACE_CONSTANTS

    ind = np.asarray(indentation, dtype=float)
    pos = ind > 0
    bb = np.zeros_like(ind)
    bb[pos] = ind[pos] ** 2
    tan = np.tan(alpha * math.pi / 180)
    P0 = HALF_SPACE_CONSTANTS[sides]["K"][0] / 2 * tan * E / (1 - nu ** 2) * bb  # (T.11), vartheta = E/(2(1 - nu^2))
    if math.isinf(H) or not pos.any():
        return P0
    ratio = np.ones_like(ind)
    ratio[pos] = _pyramid_law(sides, float(nu), base).ratios(ind[pos] * tan / H)  # chi = delta tan(alpha)/H
    return P0 * ratio


def flat_force(indentation: Any, E: float, a: float, nu: float, H: float, base: str = "bonded") -> np.ndarray:
    """Force of the flat-ended cylinder of radius ``a`` at ``indentation`` on a layer ``H`` (``inf``: Sneddon)."""
    ind = np.asarray(indentation, dtype=float)
    kappa = 1.0 if math.isinf(H) else _kappa(float(nu), base, float(a) / float(H))
    return np.where(ind > 0, 2 * E * a / (1 - nu ** 2) * kappa * ind, 0.0)


@lru_cache(maxsize=16)
def _cone_law(nu: float, base: str):
    from ..contact.any_thickness_tips import cone_law

    return cone_law(nu, base)


@lru_cache(maxsize=16)
def _pyramid_law(sides: int, nu: float, base: str):
    from ..contact.any_thickness_pyramids import pyramid_law

    return pyramid_law(sides, nu, base)


@lru_cache(maxsize=256)
def _kappa(nu: float, base: str, a_over_H: float) -> float:
    from ..contact.flat_punch import flat_punch_stiffness
    from ..layers.kernels import BondedLayer, FrictionlessLayer, IncompressibleLayer

    layer = (FrictionlessLayer(nu) if base == "frictionless" else IncompressibleLayer() if nu == 0.5
             else BondedLayer(nu))
    return float(flat_punch_stiffness(layer, a_over_H))


_FORCES = {"para": paraboloid_force, "cone": cone_force, "flat": flat_force, "pyr3s": pyramid_force,
           "pyr4s": pyramid_force}


def model_keys() -> list[str]:
    """The nanite keys of the models: ``thinlayer_<tip>_<base>``."""
    return [f"thinlayer_{t}_{b}" for t in TIPS for b in BASES]


def model_module(tip: str, base: str) -> types.ModuleType:
    """The nanite model module of one tip (``"para"``, ``"cone"``, ``"flat"``) and base, as nanite's
    ``model_hertz_paraboloidal`` is written: register it with ``nanite.model.register_model``.
    """
    from .._checks import check_choice

    check_choice(tip, tuple(TIPS), "tip")
    check_choice(base, BASES, "base")
    size, size_name, size_unit, size_default = TIPS[tip]
    force = _FORCES[tip]
    key = f"thinlayer_{tip}_{base}"

    def get_parameter_defaults():
        """Return the default model parameters (nanite's order: that of ``parameter_keys``)."""
        import lmfit

        params = lmfit.Parameters()
        params.add("E", value=3e3, min=0)
        if tip in ("cone", "pyr3s", "pyr4s"):
            params.add(size, value=size_default, min=0, max=90, vary=False)
        else:
            params.add(size, value=size_default, min=0, vary=False)
        params.add("nu", value=.5, min=0, max=0.5, vary=False)
        params.add("H", value=10e-6, min=0, vary=False)
        params.add("contact_point", value=0)
        params.add("baseline", value=0)
        return params

    func = _model_function(tip, base)
    func.__doc__ = (f"{_WORDS[tip].capitalize()} on a layer of thickness H on a {base} rigid base, any thickness "
                    f"(thinlayer).\n\n{force.__doc__}\n\nParameters: delta (tip position, negative into the sample) "
                    f"[m], E [Pa], {size} [{size_unit}], nu, H [m] (inf: the half-space), contact_point [m], "
                    "baseline [N].  Returns the force [N].")
    mod = types.ModuleType(f"thinlayer.afm.nanite_models.{key}", func.__doc__)
    mod.get_parameter_defaults = get_parameter_defaults
    mod.model_func = func
    mod.model_doc = func.__doc__
    mod.model_key = key
    mod.model_name = f"{_WORDS[tip]}, {base} layer, any thickness (thinlayer)"
    mod.parameter_keys = ["E", size, "nu", "H", "contact_point", "baseline"]
    mod.parameter_names = ["Young's Modulus", size_name, "Poisson's Ratio", "Layer Thickness", "Contact Point",
                           "Force Baseline"]
    mod.parameter_units = ["Pa", size_unit, "", "m", "m", "N"]
    mod.valid_axes_x = ["tip position"]
    mod.valid_axes_y = ["force"]
    return mod


def _model_function(tip: str, base: str):
    """The model function of nanite's convention: ``f(delta, E, <size>, nu, H, contact_point=0, baseline=0)``."""
    if tip == "para":
        def thinlayer_para(delta, E, R, nu, H, contact_point=0, baseline=0):
            return paraboloid_force(contact_point - np.asarray(delta, dtype=float), E, R, nu, H, base) + baseline
        return thinlayer_para
    if tip == "cone":
        def thinlayer_cone(delta, E, alpha, nu, H, contact_point=0, baseline=0):
            return cone_force(contact_point - np.asarray(delta, dtype=float), E, alpha, nu, H, base) + baseline
        return thinlayer_cone
    if tip in ("pyr3s", "pyr4s"):
        sides = int(tip[3])

        def thinlayer_pyramid(delta, E, alpha, nu, H, contact_point=0, baseline=0):
            return pyramid_force(contact_point - np.asarray(delta, dtype=float), E, alpha, nu, H, base,
                                 sides) + baseline
        return thinlayer_pyramid

    def thinlayer_flat(delta, E, a, nu, H, contact_point=0, baseline=0):
        return flat_force(contact_point - np.asarray(delta, dtype=float), E, a, nu, H, base) + baseline
    return thinlayer_flat


def register(keys: list[str] | None = None) -> list[Any]:
    """Register the models with nanite (all -- elastic and viscoelastic --, or those of ``keys``); returns nanite's
    ``NaniteFitModel`` objects.
    """
    from nanite.model import register_model

    known = model_keys() + visco_model_keys()
    wanted = known if keys is None else list(keys)
    bad = [k for k in wanted if k not in known]
    if bad:
        from .._checks import InputError

        raise InputError(f"unknown thinlayer nanite model {bad[0]!r}; the models: {', '.join(known)}")
    return [register_model(model_module(*k.split("_")[1:]) if k in model_keys() else
                           visco_model_module(*k.split("_")[1:])) for k in wanted]


# =============================================================================================
# viscoelastic models (issue 27 item 4): a constant-speed approach, Lee-Radok on the layer
# =============================================================================================
#: the materials: key -> (parameter keys, names, units, defaults) before the speed
VISCO_MATERIALS = {
    "sls": (("E0", "E_inf", "tau"), ("Instantaneous Modulus", "Relaxed Modulus", "Relaxation Time"), ("Pa", "Pa", "s"),
            (6e3, 3e3, 0.1)),
    "powerlaw": (("E0", "exponent", "t0"), ("Modulus At t0", "Power-Law Exponent", "Reference Time"), ("Pa", "", "s"),
                 (3e3, 0.1, 1.0)),
}
#: time nodes of the hereditary integral's grid (besides the data's own times for the SLS)
VISCO_GRID = 2049


def _unit_force(tip: str, d: np.ndarray, size: float, nu: float, H: float, base: str) -> np.ndarray:
    """The elastic force at unit Young's modulus (the elastic family's force function with ``E = 1``)."""
    if tip in ("pyr3s", "pyr4s"):
        return pyramid_force(d, 1.0, size, nu, H, base, int(tip[3]))
    return _FORCES[tip](d, 1.0, size, nu, H, base)


def visco_force(indentation: Any, material: str, m1: float, m2: float, m3: float, speed: float, tip: str, size: float,
                nu: float, H: float, base: str = "bonded") -> np.ndarray:
    r"""Lee-Radok force of a constant-speed approach on the layer (``inf``: the half-space), zero where ``<= 0``.

    The indentation grows at the constant speed ``v`` from the contact point on, ``delta = v t``, so the time since
    contact is ``delta/v`` and (Lee & Radok 1960; the correspondence at constant nu,
    :mod:`thinlayer.contact.hereditary`)

    .. math:: P(\delta) = \int_0^{\delta/v} E(\delta/v - s)\, \frac{d}{ds} f\big(v s\big)\, ds,

    ``f`` the elastic force at unit Young's modulus (the elastic model of the same tip and base).

    * ``material="sls"`` (``m1, m2, m3 = E0, E_inf, tau``): ``E(t) = E_inf + (E0 - E_inf) exp(-t/tau)``, so
      ``P = E_inf f(delta) + (E0 - E_inf) Q(delta)``, ``Q`` the exponential branch by the exact Prony recursion
      (:func:`thinlayer.contact.hereditary.hereditary_integral`, ``f`` linear in time between the nodes: the data's
      own times and a uniform grid of :data:`VISCO_GRID` nodes).  ``E0 = E_inf`` (or ``tau -> 0``) is the elastic
      model with ``E = E_inf``.
    * ``material="powerlaw"`` (``m1, m2, m3 = E0, exponent, t0``): ``E(t) = E0 (t/t0)^(-exponent)`` (the exponent
      is named so: ``alpha`` is the cone's and the pyramids' angle), product integration by
      FFT on a uniform grid of :data:`VISCO_GRID` nodes, linear interpolation to the data (relative error ~1e-6).
    """
    ind = np.asarray(indentation, dtype=float)
    out = np.zeros_like(ind)
    pos = ind > 0
    if not pos.any():
        return out
    from ..contact.hereditary import hereditary_integral
    from ..contact.materials import PowerLaw, Prony

    times = ind[pos] / speed
    grid = np.linspace(0.0, float(times.max()), VISCO_GRID)
    if material == "sls":
        E0, E_inf, tau = m1, m2, m3
        f = _unit_force(tip, ind[pos], size, nu, H, base)
        if E0 == E_inf:
            out[pos] = E_inf * f
            return out
        tg, inv = np.unique(np.concatenate([grid, times]), return_inverse=True)
        Q = hereditary_integral(Prony(0.0, [(1.0, tau)]), tg, _unit_force(tip, speed * tg, size, nu, H, base))
        out[pos] = E_inf * f + (E0 - E_inf) * Q[inv[VISCO_GRID:]]
        return out
    E0, exponent, t0 = m1, m2, m3
    P = hereditary_integral(PowerLaw(E0, t0, exponent), grid, _unit_force(tip, speed * grid, size, nu, H, base))
    out[pos] = np.interp(times, grid, P)
    return out


def visco_model_keys() -> list[str]:
    """The nanite keys of the viscoelastic models: ``thinlayer_<material>_<tip>_<base>``."""
    return [f"thinlayer_{m}_{t}_{b}" for m in VISCO_MATERIALS for t in TIPS for b in BASES]


def visco_model_module(material: str, tip: str, base: str) -> types.ModuleType:
    """The nanite model module of a viscoelastic material (``"sls"``, ``"powerlaw"``), a tip and a base:
    the approach segment of a constant-speed indentation (:func:`visco_force`).

    What it assumes: the **approach** segment only (the contact grows: Lee-Radok; a retraction needs Ting's method,
    :func:`thinlayer.fit_viscoelastic`), the indentation growing at the **constant speed** ``speed`` (fixed: the
    tip's speed into the sample, not the piezo's if the cantilever bends much) from the contact point on, the sample
    at rest before it, a constant Poisson ratio.
    """
    from .._checks import check_choice

    check_choice(material, tuple(VISCO_MATERIALS), "material")
    check_choice(tip, tuple(TIPS), "tip")
    check_choice(base, BASES, "base")
    size, size_name, size_unit, size_default = TIPS[tip]
    mkeys, mnames, munits, mdefaults = VISCO_MATERIALS[material]
    key = f"thinlayer_{material}_{tip}_{base}"

    def get_parameter_defaults():
        """Return the default model parameters (nanite's order: that of ``parameter_keys``)."""
        import lmfit

        params = lmfit.Parameters()
        params.add(mkeys[0], value=mdefaults[0], min=0)
        if material == "sls":
            params.add("E_inf", value=mdefaults[1], min=0)
            params.add("tau", value=mdefaults[2], min=0)
        else:
            params.add("exponent", value=mdefaults[1], min=0, max=1)
            params.add("t0", value=mdefaults[2], min=0, vary=False)
        params.add("speed", value=1e-6, min=0, vary=False)
        params.add(size, value=size_default, min=0, max=90 if size == "alpha" else np.inf, vary=False)
        params.add("nu", value=.5, min=0, max=0.5, vary=False)
        params.add("H", value=10e-6, min=0, vary=False)
        params.add("contact_point", value=0)
        params.add("baseline", value=0)
        return params

    func = _visco_function(material, tip, base)
    words = "standard linear solid" if material == "sls" else "power-law material"
    func.__doc__ = (f"{_WORDS[tip].capitalize()} on a layer of a {words}, thickness H, on a {base} rigid base "
                    f"(thinlayer): the approach at constant indentation speed.\n\n{visco_model_module.__doc__}\n\n"
                    f"{visco_force.__doc__}\n\nParameters: delta (tip position, negative into the sample) [m], "
                    + ", ".join(f"{k} [{u}]" for k, u in zip(mkeys, munits))
                    + f", speed [m/s], {size} [{size_unit}], nu, H [m] (inf: the half-space), contact_point [m], "
                    "baseline [N].  Returns the force [N].")
    mod = types.ModuleType(f"thinlayer.afm.nanite_models.{key}", func.__doc__)
    mod.get_parameter_defaults = get_parameter_defaults
    mod.model_func = func
    mod.model_doc = func.__doc__
    mod.model_key = key
    mod.model_name = f"{_WORDS[tip]}, {base} layer, {words}, approach (thinlayer)"
    mod.parameter_keys = [*mkeys, "speed", size, "nu", "H", "contact_point", "baseline"]
    mod.parameter_names = [*mnames, "Indentation Speed", size_name, "Poisson's Ratio", "Layer Thickness",
                           "Contact Point", "Force Baseline"]
    mod.parameter_units = [*munits, "m/s", size_unit, "", "m", "m", "N"]
    mod.valid_axes_x = ["tip position"]
    mod.valid_axes_y = ["force"]
    return mod


def _visco_function(material: str, tip: str, base: str):
    """``f(delta, <material's three>, speed, <size>, nu, H, contact_point=0, baseline=0)``, nanite's convention (the
    size argument named as the tip's parameter: nanite reads the names).
    """
    def force(delta, m1, m2, m3, speed, size, nu, H, contact_point, baseline):
        return visco_force(contact_point - np.asarray(delta, dtype=float), material, m1, m2, m3, speed, tip, size, nu,
                           H, base) + baseline

    size = TIPS[tip][0]
    if material == "sls":
        if size == "R":
            def thinlayer_sls(delta, E0, E_inf, tau, speed, R, nu, H, contact_point=0, baseline=0):
                return force(delta, E0, E_inf, tau, speed, R, nu, H, contact_point, baseline)
        elif size == "a":
            def thinlayer_sls(delta, E0, E_inf, tau, speed, a, nu, H, contact_point=0, baseline=0):
                return force(delta, E0, E_inf, tau, speed, a, nu, H, contact_point, baseline)
        else:
            def thinlayer_sls(delta, E0, E_inf, tau, speed, alpha, nu, H, contact_point=0, baseline=0):
                return force(delta, E0, E_inf, tau, speed, alpha, nu, H, contact_point, baseline)
        return thinlayer_sls
    if size == "R":
        def thinlayer_powerlaw(delta, E0, exponent, t0, speed, R, nu, H, contact_point=0, baseline=0):
            return force(delta, E0, exponent, t0, speed, R, nu, H, contact_point, baseline)
    elif size == "a":
        def thinlayer_powerlaw(delta, E0, exponent, t0, speed, a, nu, H, contact_point=0, baseline=0):
            return force(delta, E0, exponent, t0, speed, a, nu, H, contact_point, baseline)
    else:
        def thinlayer_powerlaw(delta, E0, exponent, t0, speed, alpha, nu, H, contact_point=0, baseline=0):
            return force(delta, E0, exponent, t0, speed, alpha, nu, H, contact_point, baseline)
    return thinlayer_powerlaw
