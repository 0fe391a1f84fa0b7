//! A glTF material that transmits (`KHR_materials_transmission`) as a dielectric: a thin
//! wall without `KHR_materials_volume` (glTF's default), a solid one with it.

use super::convert::Importer;
use super::material::Alpha;
use crate::error::Result;
use crate::scene_file::{
    DistributionSpec, FresnelSpec, IorSpec, MaterialSpec, RoughDielectricSpec, ScalarRef, TextureRef,
    ThinDielectricSpec,
};

impl Importer<'_> {
    /// A transmitting material: thin-walled without `KHR_materials_volume`.
    pub(super) fn dielectric(
        &mut self,
        m: &::gltf::Material,
        owner: &str,
        (base, base_mean): (TextureRef, [f64; 3]),
        alpha: Alpha,
        ior: f64,
    ) -> Result<(MaterialSpec, String)> {
        let value = IorSpec::Value;
        let volume = m.volume().is_some_and(|v| v.thickness_factor() > 0.0);
        if m.volume().is_some_and(|v| v.attenuation_distance().is_finite()) {
            self.warn(
                owner,
                "its volume's attenuation is not read: the inside is clear".into(),
            );
        }
        if !volume {
            if !alpha.is_zero() {
                self.warn(
                    owner,
                    "a thin transmitting wall is rendered smooth (its roughness is left out)".into(),
                );
            }
            let spec = ThinDielectricSpec {
                int_ior: value(ior),
                ext_ior: value(1.0),
                specular_reflectance: None,
                specular_transmittance: Some(base),
            };
            return Ok((
                MaterialSpec::ThinDielectric(spec),
                format!("thin dielectric, index {ior}"),
            ));
        }
        Ok(match alpha {
            alpha if alpha.is_zero() => {
                if !matches!(base, TextureRef::Color(_)) {
                    self.warn(
                        owner,
                        "a smooth dielectric's tint is one colour: its base colour image is averaged".into(),
                    );
                }
                let spec = MaterialSpec::Dielectric {
                    index: ior,
                    albedo: Some(base_mean),
                    fresnel: FresnelSpec::Exact,
                };
                (spec, format!("dielectric, index {ior}"))
            }
            alpha => {
                let a = match alpha {
                    Alpha::Constant(a) => ScalarRef::from(a),
                    Alpha::Texture(t, _) => ScalarRef(t),
                };
                let spec = RoughDielectricSpec {
                    int_ior: value(ior),
                    ext_ior: value(1.0),
                    specular_reflectance: None,
                    specular_transmittance: Some(base),
                    distribution: DistributionSpec::Ggx,
                    alpha: Some(a),
                    alpha_u: None,
                    alpha_v: None,
                };
                (
                    MaterialSpec::RoughDielectric(spec),
                    format!("rough dielectric (GGX), index {ior}"),
                )
            }
        })
    }
}
