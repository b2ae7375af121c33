"""clrt's normalised Phong lobe as a Mitsuba 3 BSDF plugin, `clrt_phong` (scalar variants only).

    f(w_i, w_o) = weight (n + 2) / (2 pi) max(0, R.w_o)^n,   R = w_i mirrored about N

docs/path-tracing.md defines it; Mitsuba has no such lobe. It is sampled by cos^n about the
mirror direction, with density (n + 1) / (2 pi) cos^n, as clrt samples it; directions below the
surface are lost, so it reflects less than `weight` at grazing angles. One-sided, like
Mitsuba's own reflecting BSDFs: the converter wraps it in `twosided`.
"""
import math

import mitsuba as mi


def _mirror(w):
    return mi.Vector3f(-w.x, -w.y, w.z)


class NormalisedPhong(mi.BSDF):
    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        self.weight = props.get("weight", 1.0)
        self.exponent = props.get("exponent", 1.0)
        self.m_flags = mi.BSDFFlags.GlossyReflection | mi.BSDFFlags.FrontSide
        self.m_components = [self.m_flags]

    def _cos_n(self, wi, wo):
        # x^0 is 1, as in clrt, also where the lobe's cosine is 0.
        r = _mirror(wi)
        c = max(0.0, r.x * wo.x + r.y * wo.y + r.z * wo.z)
        return 1.0 if self.exponent == 0 else c ** self.exponent

    def _value_pdf(self, si, wo):
        if si.wi.z <= 0 or wo.z <= 0:
            return 0.0, 0.0
        lobe = self._cos_n(si.wi, wo)
        n = self.exponent
        return (self.weight * (n + 2) / (2 * math.pi) * lobe * wo.z,
                (n + 1) / (2 * math.pi) * lobe)

    def sample(self, ctx, si, sample1, sample2, active=True):
        bs = mi.BSDFSample3f()
        if si.wi.z <= 0 or not ctx.is_enabled(mi.BSDFFlags.GlossyReflection):
            return bs, mi.Color3f(0.0)
        cos_alpha = sample2[0] ** (1.0 / (self.exponent + 1))
        sin_alpha = math.sqrt(max(0.0, 1.0 - cos_alpha * cos_alpha))
        phi = 2 * math.pi * sample2[1]
        local = mi.Vector3f(sin_alpha * math.cos(phi), sin_alpha * math.sin(phi), cos_alpha)
        wo = mi.Frame3f(_mirror(si.wi)).to_world(local)
        value, pdf = self._value_pdf(si, wo)
        if pdf <= 0:
            return bs, mi.Color3f(0.0)
        bs.wo, bs.pdf, bs.eta = wo, pdf, 1.0
        bs.sampled_type, bs.sampled_component = int(mi.BSDFFlags.GlossyReflection), 0
        return bs, mi.Color3f(value / pdf)

    def eval(self, ctx, si, wo, active=True):
        if not ctx.is_enabled(mi.BSDFFlags.GlossyReflection):
            return mi.Color3f(0.0)
        return mi.Color3f(self._value_pdf(si, wo)[0])

    def pdf(self, ctx, si, wo, active=True):
        if not ctx.is_enabled(mi.BSDFFlags.GlossyReflection):
            return 0.0
        return self._value_pdf(si, wo)[1]

    def eval_pdf(self, ctx, si, wo, active=True):
        if not ctx.is_enabled(mi.BSDFFlags.GlossyReflection):
            return mi.Color3f(0.0), 0.0
        value, pdf = self._value_pdf(si, wo)
        return mi.Color3f(value), pdf

    def to_string(self):
        return f"NormalisedPhong[weight={self.weight}, exponent={self.exponent}]"


def register():
    mi.register_bsdf("clrt_phong", lambda props: NormalisedPhong(props))
