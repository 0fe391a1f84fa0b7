//! Mitsuba 3's `<bsdf>` and `<texture>` plugins as the scene file's materials and
//! textures: the same definitions under the same parameter names, so most map one to one.

use super::convert::Importer;
use super::xml::{Plugin, Value};
use crate::error::Result;
use crate::scene_file::{
    ConductorSpec, DistributionSpec, IorSpec, MaterialSpec, PlasticSpec, RoughConductorSpec,
    RoughDielectricSpec, RoughPlasticSpec, ScalarRef, TextureRef, TextureSpec, ThinDielectricSpec,
    TwoSidedSpec, UvScale, WrapSpec,
};

impl Importer {
    /// The material of the `<bsdf>` plugin `b`.
    pub(super) fn material(&mut self, b: &Plugin) -> Result<MaterialSpec> {
        self.read(b);
        let asked = self.asked.clone();
        let ior = |name: &str, default: &str| -> Result<IorSpec> {
            Ok(match asked.property(b, name).map(|p| &p.value) {
                None => IorSpec::Named(default.into()),
                Some(Value::Number(x)) => IorSpec::Value(*x),
                Some(Value::Text(s)) => IorSpec::Named(s.clone()),
                Some(_) => {
                    return Err(b
                        .at
                        .error(format!("{}: `{name}` is a number or a medium's name", b.label())));
                }
            })
        };
        let distribution = match self.text(b, "distribution")?.as_deref() {
            None | Some("beckmann") => DistributionSpec::Beckmann,
            Some("ggx") => DistributionSpec::Ggx,
            Some(other) => {
                return Err(b.at.error(format!(
                    "{}: no distribution `{other}` (beckmann, ggx)",
                    b.label()
                )));
            }
        };
        Ok(match b.kind.as_str() {
            // Mitsuba's `diffuse` reflects from its front face only, this renderer's matte
            // material from both: one-sided, it is black behind (as Mitsuba's, it absorbs).
            "diffuse" => MaterialSpec::TwoSided(TwoSidedSpec {
                front: Box::new(MaterialSpec::Lambertian {
                    albedo: self
                        .texture(b, "reflectance")?
                        .unwrap_or(TextureRef::Color([0.5; 3])),
                }),
                back: Some(Box::new(MaterialSpec::Lambertian {
                    albedo: TextureRef::Color([0.0; 3]),
                })),
            }),
            "conductor" => MaterialSpec::Conductor(ConductorSpec {
                material: self.text(b, "material")?,
                eta: self.triple(b, "eta")?,
                k: self.triple(b, "k")?,
                specular_reflectance: self.texture(b, "specular_reflectance")?,
            }),
            "roughconductor" => MaterialSpec::RoughConductor(RoughConductorSpec {
                material: self.text(b, "material")?,
                eta: self.triple(b, "eta")?,
                k: self.triple(b, "k")?,
                specular_reflectance: self.texture(b, "specular_reflectance")?,
                distribution,
                alpha: self.scalar(b, "alpha")?,
                alpha_u: self.scalar(b, "alpha_u")?,
                alpha_v: self.scalar(b, "alpha_v")?,
            }),
            "dielectric" => {
                let index = |spec: IorSpec| -> Result<f64> {
                    match spec {
                        IorSpec::Value(x) => Ok(x),
                        IorSpec::Named(name) => crate::material::ior::dielectric(&name)
                            .ok_or_else(|| b.at.error(format!("{}: no medium named `{name}`", b.label()))),
                    }
                };
                let (int, ext) = (index(ior("int_ior", "bk7")?)?, index(ior("ext_ior", "air")?)?);
                let (r, t) = (
                    self.triple(b, "specular_reflectance")?,
                    self.triple(b, "specular_transmittance")?,
                );
                if r.is_some() && t.is_some() && r != t {
                    return Err(b.at.error(format!(
                        "{}: a dielectric here has one tint for reflection and transmission",
                        b.label()
                    )));
                }
                if r.is_some() != t.is_some() && r.or(t) != Some([1.0; 3]) {
                    self.warn(
                        b,
                        "its one tint is applied to reflection and transmission alike".into(),
                    );
                }
                MaterialSpec::Dielectric {
                    index: int / ext,
                    albedo: r.or(t),
                    fresnel: self.fresnel(b)?,
                }
            }
            "roughdielectric" => MaterialSpec::RoughDielectric(RoughDielectricSpec {
                int_ior: ior("int_ior", "bk7")?,
                ext_ior: ior("ext_ior", "air")?,
                specular_reflectance: self.texture(b, "specular_reflectance")?,
                specular_transmittance: self.texture(b, "specular_transmittance")?,
                distribution,
                alpha: self.scalar(b, "alpha")?,
                alpha_u: self.scalar(b, "alpha_u")?,
                alpha_v: self.scalar(b, "alpha_v")?,
            }),
            "thindielectric" => MaterialSpec::ThinDielectric(ThinDielectricSpec {
                int_ior: ior("int_ior", "bk7")?,
                ext_ior: ior("ext_ior", "air")?,
                specular_reflectance: self.texture(b, "specular_reflectance")?,
                specular_transmittance: self.texture(b, "specular_transmittance")?,
            }),
            "plastic" => MaterialSpec::Plastic(PlasticSpec {
                diffuse_reflectance: self
                    .texture(b, "diffuse_reflectance")?
                    .unwrap_or(TextureRef::Color([0.5; 3])),
                specular_reflectance: self.texture(b, "specular_reflectance")?,
                int_ior: ior("int_ior", "polypropylene")?,
                ext_ior: ior("ext_ior", "air")?,
                nonlinear: self.boolean(b, "nonlinear")?.unwrap_or(false),
            }),
            "roughplastic" => MaterialSpec::RoughPlastic(RoughPlasticSpec {
                diffuse_reflectance: self
                    .texture(b, "diffuse_reflectance")?
                    .unwrap_or(TextureRef::Color([0.5; 3])),
                specular_reflectance: self.texture(b, "specular_reflectance")?,
                int_ior: ior("int_ior", "polypropylene")?,
                ext_ior: ior("ext_ior", "air")?,
                nonlinear: self.boolean(b, "nonlinear")?.unwrap_or(false),
                distribution,
                alpha: self.number(b, "alpha")?.unwrap_or(0.1),
            }),
            "twosided" => {
                let inner: Vec<&Plugin> = b.children.iter().filter(|c| c.tag == "bsdf").collect();
                let (front, back) = match inner[..] {
                    [front] => (front, None),
                    [front, back] => (front, Some(back)),
                    _ => return Err(b.at.error(format!("{}: holds one or two <bsdf>s", b.label()))),
                };
                let front = self.face_material(front)?;
                match back.map(|p| self.face_material(p)).transpose()? {
                    // The matte material reflects from both faces already: the very material
                    // of a scene file's `lambertian` (its XML twin is written so).
                    None if matches!(front, MaterialSpec::Lambertian { .. }) => front,
                    back => MaterialSpec::TwoSided(TwoSidedSpec {
                        front: Box::new(front),
                        back: back.map(Box::new),
                    }),
                }
            }
            "normalmap" => {
                let Some(inner) = b.children.iter().find(|c| c.tag == "bsdf") else {
                    return Err(b.at.error(format!("{}: holds the <bsdf> it perturbs", b.label())));
                };
                let normal_map = self.texture(b, "normalmap")?.ok_or_else(|| {
                    b.at.error(format!("{}: needs its `normalmap` texture", b.label()))
                })?;
                // Mitsuba 3 shadows and flips perturbed normals unless told not to; here never.
                let flags = ["use_shadowing_function", "flip_invalid_normals"];
                for flag in flags {
                    if self.boolean(b, flag)? != Some(false) {
                        self.warn(
                            b,
                            format!("rendered as with `{flag}` false (Mitsuba's default is true)"),
                        );
                    }
                }
                let material = self.named_material(inner)?;
                MaterialSpec::NormalMap { normal_map, material }
            }
            "raytrace_mirror" => self.mirror(b)?,
            other => return Err(self.unsupported(b, other)),
        })
    }

    /// The material of the `<bsdf>` `b` on one face of a `twosided`: a `diffuse` is the
    /// matte material itself (not black behind: the `twosided` gives its back).
    fn face_material(&mut self, b: &Plugin) -> Result<MaterialSpec> {
        Ok(match self.material(b)? {
            MaterialSpec::TwoSided(t) if b.kind == "diffuse" => *t.front,
            other => other,
        })
    }

    /// The colour parameter `name` of `p`: a colour, a number (grey) or a nested texture.
    pub(super) fn texture(&mut self, p: &Plugin, name: &str) -> Result<Option<TextureRef>> {
        if let Some(t) = p
            .children
            .iter()
            .find(|c| c.tag == "texture" && c.name.as_deref() == Some(name))
        {
            return self
                .texture_plugin(t)
                .map(|spec| Some(TextureRef::Inline(Box::new(spec))));
        }
        Ok(self.triple(p, name)?.map(TextureRef::Color))
    }

    /// The number parameter `name` of `p` that may be a texture (a roughness). Mitsuba
    /// looks a `checkerboard` up as a number with its colours swapped (`color1` where as
    /// a colour it is `color0`) and each colour's channels averaged; the scene file reads
    /// a colour's first channel, so the colours are swapped and made grey here.
    fn scalar(&mut self, p: &Plugin, name: &str) -> Result<Option<ScalarRef>> {
        let mut texture = self.texture(p, name)?;
        if let Some(TextureRef::Inline(spec)) = &mut texture
            && let TextureSpec::Checkerboard { color0, color1, .. } = spec.as_mut()
        {
            // A grey colour stays as written ((x + x + x)/3 need not round back to x).
            let grey = |c: [f64; 3]| match c {
                [r, g, b] if r == g && g == b => c,
                [r, g, b] => [(r + g + b) / 3.0; 3],
            };
            (*color0, *color1) = (grey(*color1), grey(*color0));
        }
        Ok(texture.map(ScalarRef))
    }

    /// A `<texture>` plugin: `bitmap` or `checkerboard`.
    fn texture_plugin(&mut self, t: &Plugin) -> Result<TextureSpec> {
        self.read(t);
        let (scale, offset) = self.to_uv(t)?;
        Ok(match t.kind.as_str() {
            "checkerboard" => TextureSpec::Checkerboard {
                color0: self.triple(t, "color0")?.unwrap_or([0.4; 3]),
                color1: self.triple(t, "color1")?.unwrap_or([0.2; 3]),
                scale,
                offset,
            },
            "bitmap" => {
                let wrap = match self.text(t, "wrap_mode")?.as_deref() {
                    None | Some("repeat") => WrapSpec::Repeat,
                    Some("clamp") => WrapSpec::Clamp,
                    Some(other) => {
                        return Err(t.at.error(format!(
                            "{}: wrap_mode `{other}` is not read (repeat, clamp)",
                            t.label()
                        )));
                    }
                };
                if let Some(filter) = self.text(t, "filter_type")?.filter(|f| f != "bilinear") {
                    self.warn(t, format!("filter_type `{filter}` is rendered bilinear"));
                }
                let file = self
                    .text(t, "filename")?
                    .ok_or_else(|| t.at.error(format!("{}: needs a `filename`", t.label())))?;
                TextureSpec::Image {
                    file: self.path_of(&file),
                    wrap,
                    // Mitsuba decodes sRGB unless told `raw`, a normal map's image too.
                    raw: Some(self.boolean(t, "raw")?.unwrap_or(false)),
                    scale,
                    offset,
                }
            }
            other => return Err(self.unsupported(t, other)),
        })
    }

    /// A texture's `to_uv`: a scale and an offset of `uv`, nothing else.
    fn to_uv(&self, t: &Plugin) -> Result<(UvScale, [f64; 2])> {
        let Some(p) = self.property(t, "to_uv") else {
            return Ok((UvScale::Uniform(1.0), [0.0; 2]));
        };
        let Value::Transform(t) = &p.value else {
            return Err(p.at.error("`to_uv` is a <transform>"));
        };
        let r = t.map.rows();
        if r[0][1] != 0.0 || r[1][0] != 0.0 {
            return Err(p
                .at
                .error("`to_uv` may scale and translate uv here, not turn or shear it"));
        }
        Ok((UvScale::PerAxis([r[0][0], r[1][1]]), [r[0][3], r[1][3]]))
    }
}
