"""The Mitsuba 3 BSDF "diffract": a patch's diffraction BRDF from the table `diffract export --mitsuba OUT.json` writes.

The table holds the lobes method's spectral factor in linear sRGB over (u, v, w) = -omega_i - omega_r (both
directions pointing away from the surface, in the surface's local frame: x along the height field's columns, y along
its rows); the gain factor, Stam's shadowing and the Fresnel term stay analytic here because they vary fast near the
horizon. Usage (docs/guide/mitsuba.md):

    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    import diffract_mitsuba
    diffract_mitsuba.register()
    bsdf = mi.load_dict({"type": "diffract", "filename": "table.json"})

Runs in scalar_rgb and llvm_ad_rgb: the lookup is a drjit texture and the rest is drjit arithmetic.
"""
import json
import math
import os

import drjit as dr
import mitsuba as mi
import numpy as np

FORMAT = "diffract-brdf-table"


def _load(filename):
    with open(filename) as f:
        header = json.load(f)
    if header.get("format") != FORMAT or header.get("version") != 1:
        raise ValueError(f"{filename}: not a {FORMAT} version 1 header (write it with diffract export --mitsuba)")
    data = np.load(os.path.join(os.path.dirname(os.path.abspath(filename)), header["data"]))
    if list(data.shape) != list(header["shape"]):
        raise ValueError(f"{filename}: the table's shape {data.shape} is not the header's {header['shape']}")
    return header, np.ascontiguousarray(data, dtype=np.float32)


def _max(a, b):
    # a select rather than dr.maximum: some LLVM builds cannot lower the fmaximum that dr.maximum becomes
    return dr.select(a > b, a, b)


def _min(a, b):
    return dr.select(a < b, a, b)


class DiffractBSDF(mi.BSDF):
    """Reflection only, front side, anisotropic; importance-samples the cosine (the orders are found by light
    sampling: give the scene an emitter that is sampled, e.g. a directional, point or small area light)."""

    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        filename = str(props["filename"])
        header, data = _load(filename)
        self.header = header
        self.n_w, self.n_uv = data.shape[0], data.shape[1]
        self.uv_min, self.uv_max = header["uv_range"]
        self.w_min, self.w_max = header["w_range"]
        # texels sit at (i + 0.5) / n in texture coordinates; the table's nodes at i / (n - 1) of its range
        self.table = mi.Texture3f(mi.TensorXf(data), use_accel=False, filter_mode=dr.FilterMode.Linear,
                                  wrap_mode=dr.WrapMode.Clamp)
        self.r0 = float(header["schlick_r0"])
        self.gain = header["gain"]
        self.n = float(header["refractive_index"])
        # mode "absolute": the BRDF in 1/sr (relative x radiometric_gain / pi); "relative": brdfmap's values / pi,
        # so that scale 1 shows what a BRDF map shows under a light of irradiance pi
        mode = props.get("mode", "absolute") if props.has_property("mode") else "absolute"
        if mode not in ("absolute", "relative"):
            raise ValueError(f"diffract: mode must be absolute or relative, got {mode}")
        scale = props.get("scale", 1.0) if props.has_property("scale") else 1.0
        gain = float(header["radiometric_gain"]) if mode == "absolute" else 1.0
        self.scale = float(scale) * gain / math.pi
        # saturated orders lie outside the sRGB gamut (negative channels), which Mitsuba's image blocks refuse as
        # invalid samples: clipped by default; unclipped ("clip": False) the values are brdfmap's PFM values
        self.clip = bool(props.get("clip", True)) if props.has_property("clip") else True
        flags = mi.BSDFFlags.GlossyReflection | mi.BSDFFlags.FrontSide | mi.BSDFFlags.Anisotropic
        self.m_flags = flags
        self.m_components = [flags]

    def _coordinate(self, x, lo, hi, n):
        return ((x - lo) / (hi - lo) * (n - 1) + 0.5) / n

    def spectral_factor(self, u, v, w):
        """The table at (u, v, w), trilinear, clamped: linear sRGB."""
        pos = mi.Point3f(self._coordinate(u, self.uv_min, self.uv_max, self.n_uv),
                         self._coordinate(v, self.uv_min, self.uv_max, self.n_uv),
                         self._coordinate(w, self.w_min, self.w_max, self.n_w))
        c = self.table.eval(pos)
        return mi.Color3f(c[0], c[1], c[2])

    def rayleigh_rice(self, wl, wv):
        """Rayleigh-Rice's gain, 4 cos^2 theta_i cos theta_r Q / (R_0 w^2) (diffract.optics.illumination.GainFactor.rayleighRice)."""
        eps = self.n * self.n
        ci = _max(wl.z, 1e-30)
        cr = _max(wv.z, 1e-30)
        si2 = _max(1.0 - ci * ci, 0.0)
        sr2 = _max(1.0 - cr * cr, 0.0)
        ri = dr.sqrt(eps - si2)
        rr = dr.sqrt(eps - sr2)
        sin_product = dr.sqrt(si2 * sr2)
        cos_part = -(wl.x * wv.x + wl.y * wv.y)
        sin_part = wl.x * wv.y - wl.y * wv.x
        defined = sin_product >= 1e-12
        safe = _max(sin_product, 1e-12)
        cos_phi = dr.select(defined, cos_part / safe, 1.0)
        cos2 = dr.select(defined, cos_part * cos_part / (safe * safe), 1.0)
        sin2 = dr.select(defined, sin_part * sin_part / (safe * safe), 0.0)
        e1 = eps - 1.0
        ss = e1 / ((ci + ri) * (cr + rr))
        sp = e1 * rr / ((ci + ri) * (eps * cr + rr))
        ps = e1 * ri / ((eps * ci + ri) * (cr + rr))
        pp = e1 * (ri * rr * cos_phi - eps * sin_product) / ((eps * ci + ri) * (eps * cr + rr))
        q = 0.5 * (ss * ss * cos2 + (sp * sp + ps * ps) * sin2 + pp * pp)
        w = ci + cr
        return 4.0 * ci * ci * cr * q / (self.r0 * w * w)

    def relative(self, wl, wv):
        """brdfmap's value, the relative BRDF in linear sRGB, for the light direction wl and the view direction wv
        (local frame, both pointing away from the surface); 0 below the horizon."""
        above = (wl.z > 0) & (wv.z > 0)
        if self.gain == "rayleigh-rice":
            factor = self.spectral_factor(-(wl.x + wv.x), -(wl.y + wv.y), -(wl.z + wv.z))
            return dr.select(above, factor * self.rayleigh_rice(wl, wv), mi.Color3f(0.0))
        h = wl + wv
        length = _max(dr.norm(h), 1e-30)
        cos_half_view = _min(_max(dr.dot(wv, h) / length, 0.0), 1.0)
        m = 1.0 - cos_half_view
        fresnel = self.r0 + (1.0 - self.r0) * m * m * m * m * m
        ratio = fresnel / self.r0
        phi = ratio * ratio if self.gain == "thesis" else ratio
        one_plus_dot = 1.0 + dr.dot(wl, wv)
        wz = wl.z + wv.z
        gain = phi * one_plus_dot * one_plus_dot / _max(wz * wz * wv.z, 1e-30)
        n_dot_h = h.z / length
        v_dot_h = _max(cos_half_view, 1e-30)
        shadowing = _min(1.0, _min(2.0 * n_dot_h * wv.z / v_dot_h, 2.0 * n_dot_h * wl.z / v_dot_h))
        factor = self.spectral_factor(-h.x, -h.y, -wz)
        return dr.select(above, factor * (gain * shadowing), mi.Color3f(0.0))

    def eval(self, ctx, si, wo, active=True):
        # Mitsuba's si.wi points to the viewer (the path's previous vertex) and wo to the light: f(wo, wi) cos(wo)
        value = self.relative(wo, si.wi) * (self.scale * _max(wo.z, 0.0))
        if self.clip:
            value = _max(value, 0.0)
        return dr.select(active, value, mi.Color3f(0.0))

    def pdf(self, ctx, si, wo, active=True):
        return dr.select(active & (si.wi.z > 0), mi.warp.square_to_cosine_hemisphere_pdf(wo), 0.0)

    def sample(self, ctx, si, sample1, sample2, active=True):
        wo = mi.warp.square_to_cosine_hemisphere(sample2)
        pdf = mi.warp.square_to_cosine_hemisphere_pdf(wo)
        bs = mi.BSDFSample3f()
        bs.wo = wo
        bs.pdf = pdf
        bs.eta = 1.0
        bs.sampled_type = mi.UInt32(+mi.BSDFFlags.GlossyReflection)
        bs.sampled_component = 0
        ok = active & (si.wi.z > 0) & (pdf > 0)
        value = self.eval(ctx, si, wo, ok) / _max(pdf, 1e-30)
        return (bs, dr.select(ok, value, mi.Color3f(0.0)))

    def eval_pdf(self, ctx, si, wo, active=True):
        return self.eval(ctx, si, wo, active), self.pdf(ctx, si, wo, active)

    def traverse(self, callback):
        pass

    def to_string(self):
        return (f"DiffractBSDF[patch={self.header.get('patch')}, table={self.n_uv}x{self.n_uv}x{self.n_w}, "
                f"scale={self.scale}]")


def register():
    """Registers the plugin as "diffract" (after mi.set_variant)."""
    mi.register_bsdf("diffract", lambda props: DiffractBSDF(props))
