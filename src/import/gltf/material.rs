//! glTF's metallic-roughness materials mapped onto the renderer's BSDFs (the mapping
//! `docs/SCENE_FORMAT.md` writes down):
//!
//! - `α = roughness²` (GGX), the roughness being `roughnessFactor` times the
//!   metallic-roughness image's green channel;
//! - an emissive material (`emissiveFactor · emissive_strength`, times the mean of its
//!   emissive image, not black) → `emissive`, reflecting as a matte surface of its mean
//!   base colour;
//! - `KHR_materials_transmission` `≥ ½` → a dielectric of `KHR_materials_ior` (1.5 by
//!   default) that transmits the base colour: `thindielectric` without
//!   `KHR_materials_volume` (glTF's thin walls), else `dielectric` (`α = 0`) or
//!   `roughdielectric`;
//! - metallic `≥ ½` → `conductor` (`α = 0`) or `roughconductor` reflecting the base colour
//!   at every angle (a perfect mirror's Fresnel times the base colour);
//! - else → `plastic` (`α = 0`) or `roughplastic`: the base colour as the diffuse base
//!   under a coat of the material's index;
//! - `doubleSided` → `twosided` (a dielectric is two-sided already), a normal image →
//!   `normalmap` over the rest.
//!
//! What varies over the surface where the BSDF holds one number (metallic, a plastic's
//! `α`, emission) is averaged over the image, and a warning names it when it matters.

use super::convert::Importer;
use super::images::{Derive, mean};
use crate::error::Result;
use crate::scene_file::{
    ConductorSpec, DistributionSpec, IorSpec, MaterialSpec, PlasticSpec, RoughConductorSpec,
    RoughPlasticSpec, ScalarRef, TextureRef, TwoSidedSpec,
};
use ::gltf::material::AlphaMode;

/// A material's roughness as the BSDFs take it.
pub(super) enum Alpha {
    /// One `α` everywhere.
    Constant(f64),
    /// An `α` image, and its mean.
    Texture(TextureRef, f64),
}

impl Alpha {
    /// Whether it is `0` everywhere: a smooth surface.
    pub(super) fn is_zero(&self) -> bool {
        matches!(self, Self::Constant(a) if *a == 0.0)
    }
}

impl Importer<'_> {
    /// The scene file's name for glTF material `m` (`None`: glTF's default material),
    /// made the first time it is asked for.
    pub(super) fn material(&mut self, m: &::gltf::Material) -> Result<String> {
        if let Some(name) = self.materials.get(&m.index()) {
            return Ok(name.clone());
        }
        let owner = match m.index() {
            Some(i) => format!("materials[{i}]"),
            None => "the default material".to_string(),
        };
        let name = match (m.index(), m.name()) {
            (None, _) => "glTF default".to_string(),
            (Some(_), Some(n)) if !n.is_empty() => n.to_string(),
            (Some(i), _) => format!("material {i}"),
        };
        let name = self.unused(name, m.index());
        let (spec, what) = self.surface(m, &owner)?;
        let uv_free = spec.textures().iter().all(|t| matches!(t, TextureRef::Color(_)));
        let emits = matches!(spec, MaterialSpec::Emissive { .. });
        let normal = match m.normal_texture().filter(|_| !emits) {
            Some(n) => {
                let derive = Derive::Normal(f64::from(n.scale()));
                let at = (owner.as_str(), "normalTexture");
                let used = (&n.texture(), n.tex_coord(), None);
                Some(
                    self.images
                        .texture(used, derive, at, &mut self.assets, &mut self.warnings)?,
                )
            }
            None => None,
        };
        if m.normal_texture().is_some() && emits {
            self.warn(&owner, "an emitter is shaded without its normal map here".into());
        }
        let two_sided = m.double_sided() && !emits && !is_dielectric(&spec);
        let wrap = |inner: MaterialSpec| match two_sided {
            true => MaterialSpec::TwoSided(TwoSidedSpec {
                front: Box::new(inner),
                back: None,
            }),
            false => inner,
        };
        let top = match normal {
            Some(map) => {
                let surface = self.unused(format!("{name} (surface)"), m.index());
                self.file.materials.insert(surface.clone(), spec);
                wrap(MaterialSpec::NormalMap {
                    normal_map: map,
                    material: surface,
                })
            }
            None => wrap(spec),
        };
        if m.alpha_mode() != AlphaMode::Opaque {
            self.warn(
                &owner,
                format!(
                    "alphaMode {:?}: rendered opaque (alpha is not read)",
                    m.alpha_mode()
                ),
            );
        }
        let sides = if two_sided { ", two-sided" } else { "" };
        let mapped = if m.normal_texture().is_some() && !emits {
            ", normal-mapped"
        } else {
            ""
        };
        self.read
            .push(format!("{owner} → `{name}`: {what}{sides}{mapped}"));
        self.file.materials.insert(name.clone(), top);
        self.materials.insert(m.index(), name.clone());
        if uv_free && !emits && m.normal_texture().is_none() {
            self.plain_materials.insert(name.clone());
        }
        Ok(name)
    }

    /// `name`, or (if a material has it already: two glTF materials of one name) it with
    /// the glTF material's index, and then a count, after it.
    fn unused(&self, name: String, index: Option<usize>) -> String {
        let taken = |n: &String| self.file.materials.contains_key(n);
        if !taken(&name) {
            return name;
        }
        let tag = index.map_or(String::from("default"), |i| i.to_string());
        (1..)
            .map(|k| {
                if k == 1 {
                    format!("{name} ({tag})")
                } else {
                    format!("{name} ({tag}, {k})")
                }
            })
            .find(|n| !taken(n))
            .unwrap_or(name)
    }

    /// The BSDF of `m` (without its normal map and sides) and what it was mapped to.
    fn surface(&mut self, m: &::gltf::Material, owner: &str) -> Result<(MaterialSpec, String)> {
        let pbr = m.pbr_metallic_roughness();
        let [r, g, b, _] = pbr.base_color_factor().map(f64::from);
        let factor = [r, g, b];
        let base_mean = match pbr.base_color_texture() {
            Some(info) => {
                let image = info.texture().source().index();
                let plain = self.images.decoded(image, false, &mut self.assets)?;
                let mean = mean(&plain);
                [0, 1, 2].map(|k| mean[k] * factor[k])
            }
            None => factor,
        };
        if let Some(radiance) = self.emission(m, owner)? {
            let albedo = base_mean.map(|c| c.clamp(0.0, 1.0));
            self.warn(
                owner,
                format!(
                    "emits {radiance:?}: reflects here as a matte surface of its mean base colour {albedo:?} (an \
                     emitter's surface is matte)"
                ),
            );
            let spec = MaterialSpec::Emissive {
                radiance,
                two_sided: m.double_sided(),
                albedo: Some(albedo),
            };
            return Ok((spec, format!("emissive, radiance {radiance:?}")));
        }
        let base = match pbr.base_color_texture() {
            Some(info) => self.texture(&info, Derive::Color(factor), (owner, "baseColorTexture"))?,
            None => TextureRef::Color(factor),
        };
        let (metallic, alpha) = self.metallic_roughness(&pbr, owner)?;
        let ior = f64::from(m.ior().unwrap_or(1.5));
        let coat = |x: f64| IorSpec::Value(x);

        let transmission = match m.transmission() {
            Some(t) => {
                if t.transmission_texture().is_some() {
                    self.warn(
                        owner,
                        "its transmission image is not read: transmissionFactor alone".into(),
                    );
                }
                f64::from(t.transmission_factor())
            }
            None => 0.0,
        };
        if transmission > 0.0 && transmission < 1.0 {
            let as_ = if transmission >= 0.5 {
                "a dielectric"
            } else {
                "opaque"
            };
            self.warn(owner, format!("transmission {transmission}: rendered as {as_}"));
        }
        if transmission >= 0.5 {
            return self.dielectric(m, owner, (base, base_mean), alpha, ior);
        }
        if metallic > 0.0 && metallic < 1.0 {
            let as_ = if metallic >= 0.5 {
                "a metal"
            } else {
                "a dielectric"
            };
            self.warn(
                owner,
                format!("metallic {metallic:.3}: rendered as {as_} (no blend of the two)"),
            );
        }
        let ggx = DistributionSpec::Ggx;
        if metallic >= 0.5 {
            return Ok(match alpha {
                alpha if alpha.is_zero() => (
                    MaterialSpec::Conductor(ConductorSpec {
                        specular_reflectance: Some(base),
                        ..ConductorSpec::default()
                    }),
                    "smooth metal (conductor)".into(),
                ),
                alpha => {
                    let (a, what) = match alpha {
                        Alpha::Constant(a) => (ScalarRef::from(a), format!("α {a:.4}")),
                        Alpha::Texture(t, mean) => {
                            (ScalarRef(t), format!("α from the image, mean {mean:.4}"))
                        }
                    };
                    let spec = RoughConductorSpec {
                        material: None,
                        eta: None,
                        k: None,
                        specular_reflectance: Some(base),
                        distribution: ggx,
                        alpha: Some(a),
                        alpha_u: None,
                        alpha_v: None,
                    };
                    (
                        MaterialSpec::RoughConductor(spec),
                        format!("rough metal (roughconductor, GGX, {what})"),
                    )
                }
            });
        }
        let alpha = match alpha {
            Alpha::Constant(a) => a,
            Alpha::Texture(_, mean) => {
                self.warn(
                    owner,
                    format!("a rough plastic has one roughness here: its roughness image is averaged (α {mean:.4})"),
                );
                mean
            }
        };
        Ok(if alpha == 0.0 {
            let spec = PlasticSpec {
                diffuse_reflectance: base,
                specular_reflectance: None,
                int_ior: coat(ior),
                ext_ior: coat(1.0),
                nonlinear: false,
            };
            (
                MaterialSpec::Plastic(spec),
                format!("smooth plastic, coat index {ior}"),
            )
        } else {
            let spec = RoughPlasticSpec {
                diffuse_reflectance: base,
                specular_reflectance: None,
                int_ior: coat(ior),
                ext_ior: coat(1.0),
                nonlinear: false,
                distribution: ggx,
                alpha,
            };
            let what = format!("rough plastic (roughplastic, GGX, α {alpha:.4}), coat index {ior}");
            (MaterialSpec::RoughPlastic(spec), what)
        })
    }

    /// The metallic value (the factor times the mean of the image's blue channel) and the
    /// roughness as `α`; a warning when the image holds both metal and dielectric texels.
    fn metallic_roughness(
        &mut self,
        pbr: &::gltf::material::PbrMetallicRoughness,
        owner: &str,
    ) -> Result<(f64, Alpha)> {
        let (mf, rf) = (
            f64::from(pbr.metallic_factor()),
            f64::from(pbr.roughness_factor()),
        );
        let Some(info) = pbr.metallic_roughness_texture() else {
            return Ok((mf, Alpha::Constant(rf * rf)));
        };
        let image = info.texture().source().index();
        let data = self.images.decoded(image, true, &mut self.assets)?;
        let texels = data.pixels().len().max(1) as f64;
        let metal = data
            .pixels()
            .iter()
            .filter(|p| f64::from(p[2]) * mf >= 0.5)
            .count() as f64
            / texels;
        let metallic = mean(&data)[2] * mf;
        if metal > 0.0 && metal < 1.0 {
            self.warn(
                owner,
                format!(
                    "metallic varies over its image ({:.1} % of texels metal): the whole surface is rendered as \
                     its mean, {metallic:.3}",
                    100.0 * metal
                ),
            );
        }
        let alpha_mean = data
            .pixels()
            .iter()
            .map(|p| {
                (f64::from(p[1]) * rf)
                    .powi(2)
                    .max(crate::material::microfacet::MIN_ALPHA)
            })
            .sum::<f64>()
            / texels;
        let t = self.texture(&info, Derive::Alpha(rf), (owner, "metallicRoughnessTexture"))?;
        Ok((metallic, Alpha::Texture(t, alpha_mean)))
    }

    /// The radiance `m` gives off, if any: `emissiveFactor · emissive_strength`, times the
    /// mean of its emissive image (the renderer's emitters are uniform).
    fn emission(&mut self, m: &::gltf::Material, owner: &str) -> Result<Option<[f64; 3]>> {
        let strength = f64::from(m.emissive_strength().unwrap_or(1.0));
        let mut radiance = m.emissive_factor().map(|c| f64::from(c) * strength);
        if let Some(info) = m.emissive_texture() {
            let image = info.texture().source().index();
            let plain = self.images.decoded(image, false, &mut self.assets)?;
            let mean = mean(&plain);
            radiance = [0, 1, 2].map(|k| radiance[k] * mean[k]);
            if radiance != [0.0; 3] {
                self.warn(
                    owner,
                    "its emissive image is averaged to one radiance (an emitter is uniform here)".into(),
                );
            }
        }
        Ok((radiance != [0.0; 3]).then_some(radiance))
    }
}

/// Whether `spec` transmits (and so may not be wrapped two-sided: it has two sides).
fn is_dielectric(spec: &MaterialSpec) -> bool {
    matches!(
        spec,
        MaterialSpec::Dielectric { .. } | MaterialSpec::RoughDielectric(_) | MaterialSpec::ThinDielectric(_)
    )
}
