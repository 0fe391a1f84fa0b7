//! The value a constructor rejected, as a type: a caller routes an error by its field, never
//! by its message's text.

use std::fmt;

/// One parameter of a library constructor: what an [`Error::InvalidValue`](super::Error)
/// is about.
///
/// A scene file maps each to the key it is written under with a `match` that names every
/// variant, so a field added here without a key does not compile.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Field {
    /// [`Sphere::new`](crate::Sphere::new)'s centre.
    SphereCenter,
    /// [`Sphere::new`](crate::Sphere::new)'s radius.
    SphereRadius,
    /// [`Plane::new`](crate::Plane::new)'s point.
    PlanePoint,
    /// [`Plane::new`](crate::Plane::new)'s normal.
    PlaneNormal,
    /// [`Triangle::new`](crate::Triangle::new)'s first vertex, `A`.
    TriangleA,
    /// [`Triangle::new`](crate::Triangle::new)'s second vertex, `B`.
    TriangleB,
    /// [`Triangle::new`](crate::Triangle::new)'s third vertex, `C`.
    TriangleC,
    /// A triangle as a whole: its vertices are finite but it has no area.
    Triangle,
    /// [`Mesh::new`](crate::Mesh::new)'s vertices and triangles, as a whole.
    Mesh,
    /// A [`Disk`](crate::shape::Disk)'s centre.
    DiskCenter,
    /// [`Disk::new`](crate::shape::Disk::new)'s normal.
    DiskNormal,
    /// [`Disk::new`](crate::shape::Disk::new)'s radius.
    DiskRadius,
    /// [`Disk::with_axes`](crate::shape::Disk::with_axes)'s axes `U` and `V`, together.
    DiskAxes,
    /// [`Mirror::new`](crate::Mirror::new)'s albedo.
    MirrorAlbedo,
    /// [`Lambertian::new`](crate::Lambertian::new)'s albedo.
    MatteAlbedo,
    /// [`Dielectric::new`](crate::Dielectric::new)'s refractive index.
    RefractiveIndex,
    /// [`Dielectric::with_albedo`](crate::Dielectric::with_albedo)'s tint.
    DielectricAlbedo,
    /// [`Emissive::new`](crate::Emissive::new)'s (and [`Emission::new`](crate::Emission::new)'s) radiance.
    EmittedRadiance,
    /// [`Emissive::with_albedo`](crate::Emissive::with_albedo)'s albedo.
    EmissiveAlbedo,
    /// [`Checkerboard::new`](crate::texture::Checkerboard::new)'s first colour.
    CheckerboardColor0,
    /// [`Checkerboard::new`](crate::texture::Checkerboard::new)'s second colour.
    CheckerboardColor1,
    /// [`UvMap::new`](crate::texture::UvMap::new)'s scale.
    TextureScale,
    /// [`UvMap::new`](crate::texture::UvMap::new)'s offset.
    TextureOffset,
    /// A conductor's real index `η` ([`Metal::new`](crate::material::Metal::new)).
    ConductorEta,
    /// A conductor's extinction coefficient `k` ([`Metal::new`](crate::material::Metal::new)).
    ConductorK,
    /// A named conductor ([`Metal::named`](crate::material::Metal::named)) that is not known.
    ConductorName,
    /// A material's factor on its specular reflection (`specular_reflectance`).
    SpecularReflectance,
    /// A material's factor on its specular transmission (`specular_transmittance`).
    SpecularTransmittance,
    /// A plastic's diffuse base (`diffuse_reflectance`).
    DiffuseReflectance,
    /// An isotropic roughness `α` ([`Roughness::isotropic`](crate::material::Roughness::isotropic)).
    Alpha,
    /// An anisotropic roughness along the tangent, `αu` ([`Roughness::anisotropic`](crate::material::Roughness::anisotropic)).
    AlphaU,
    /// An anisotropic roughness along the bitangent, `αv` ([`Roughness::anisotropic`](crate::material::Roughness::anisotropic)).
    AlphaV,
    /// The index of refraction inside a dielectric interface (`int_ior`).
    InteriorIndex,
    /// The index of refraction outside a dielectric interface (`ext_ior`).
    ExteriorIndex,
    /// [`TwoSided::new`](crate::material::TwoSided::new)'s material for the front face.
    TwoSidedFront,
    /// [`TwoSided::with_back`](crate::material::TwoSided::with_back)'s material for the back face.
    TwoSidedBack,
    /// [`PointLight::new`](crate::PointLight::new)'s position.
    LightPosition,
    /// [`PointLight::new`](crate::PointLight::new)'s (and [`SpotLight::new`](crate::light::SpotLight::new)'s) intensity.
    LightIntensity,
    /// [`SpotLight::new`](crate::light::SpotLight::new)'s and [`DirectionalLight::new`](crate::light::DirectionalLight::new)'s direction.
    LightDirection,
    /// [`DirectionalLight::new`](crate::light::DirectionalLight::new)'s irradiance.
    LightIrradiance,
    /// [`SpotLight::new`](crate::light::SpotLight::new)'s cutoff angle.
    SpotCutoff,
    /// [`SpotLight::new`](crate::light::SpotLight::new)'s beam width.
    SpotBeamWidth,
    /// [`Background::solid`](crate::Background::solid)'s colour.
    BackgroundColor,
    /// [`Background::sky`](crate::Background::sky)'s colour straight down.
    SkyHorizon,
    /// [`Background::sky`](crate::Background::sky)'s colour straight up.
    SkyZenith,
    /// An [`EnvironmentMap`](crate::background::EnvironmentMap)'s image (its size, its texels).
    EnvironmentMap,
    /// An [`EnvironmentMap`](crate::background::EnvironmentMap)'s scale.
    EnvironmentScale,
    /// [`Background::map`](crate::Background::map)'s rotation.
    EnvironmentRotation,
    /// An [`Affine`](crate::transform::Affine) transform's matrix.
    Transform,
    /// [`LookAtCamera::new`](crate::LookAtCamera::new)'s eye, `from`.
    CameraFrom,
    /// [`LookAtCamera::new`](crate::LookAtCamera::new)'s target, `at`.
    CameraAt,
    /// The look-at camera's view direction `from − at` (zero when `from == at`).
    CameraView,
    /// [`LookAtCamera::new`](crate::LookAtCamera::new)'s up vector.
    CameraUp,
    /// [`LookAtCamera::new`](crate::LookAtCamera::new)'s vertical field of view.
    CameraVfov,
    /// [`LookAtCamera::with_lens`](crate::LookAtCamera::with_lens)'s aperture radius.
    CameraAperture,
    /// [`LookAtCamera::with_lens`](crate::LookAtCamera::with_lens)'s focus distance.
    CameraFocusDistance,
    /// [`ScreenCamera::translated`](crate::ScreenCamera::translated)'s eye.
    CameraEye,
    /// An image width one camera cannot take ([`ScreenCamera::with_width`](crate::ScreenCamera::with_width): odd, or below 4).
    ImageWidth,
    /// An image's width and height together (too small, too many pixels, not 2:1 for the
    /// spec's camera).
    ImageSize,
    /// [`RenderSettings`](crate::RenderSettings)' samples per pixel.
    SamplesPerPixel,
    /// [`RenderSettings`](crate::RenderSettings)' recursion limit.
    MaxDepth,
    /// [`Tonemap::new`](crate::image::Tonemap::new)'s exposure.
    Exposure,
    /// A parameter of a type outside the library (a user's own shape or material), named
    /// by its author: `Error::invalid("torus radius", …)` makes one.
    Custom(&'static str),
}

/// A user type's parameter, by its name.
impl From<&'static str> for Field {
    fn from(name: &'static str) -> Self {
        Self::Custom(name)
    }
}

impl Field {
    /// What the field is, in a few words (`"sphere radius"`): how messages name it.
    pub fn name(self) -> &'static str {
        match self {
            Self::SphereCenter => "sphere centre",
            Self::SphereRadius => "sphere radius",
            Self::PlanePoint => "plane point",
            Self::PlaneNormal => "plane normal",
            Self::TriangleA => "triangle vertex A",
            Self::TriangleB => "triangle vertex B",
            Self::TriangleC => "triangle vertex C",
            Self::Triangle => "triangle",
            Self::Mesh => "mesh",
            Self::DiskCenter => "disk centre",
            Self::DiskNormal => "disk normal",
            Self::DiskRadius => "disk radius",
            Self::DiskAxes => "disk axes",
            Self::MirrorAlbedo => "mirror albedo",
            Self::MatteAlbedo => "matte albedo",
            Self::RefractiveIndex => "refractive index",
            Self::DielectricAlbedo => "dielectric albedo",
            Self::EmittedRadiance => "emitted radiance",
            Self::EmissiveAlbedo => "emissive albedo",
            Self::CheckerboardColor0 => "checkerboard colour 0",
            Self::CheckerboardColor1 => "checkerboard colour 1",
            Self::TextureScale => "texture uv scale",
            Self::TextureOffset => "texture uv offset",
            Self::ConductorEta => "conductor index η",
            Self::ConductorK => "conductor extinction k",
            Self::ConductorName => "conductor name",
            Self::SpecularReflectance => "specular reflectance",
            Self::SpecularTransmittance => "specular transmittance",
            Self::DiffuseReflectance => "diffuse reflectance",
            Self::Alpha => "roughness α",
            Self::AlphaU => "roughness αu",
            Self::AlphaV => "roughness αv",
            Self::InteriorIndex => "interior index of refraction",
            Self::ExteriorIndex => "exterior index of refraction",
            Self::TwoSidedFront => "two-sided front material",
            Self::TwoSidedBack => "two-sided back material",
            Self::LightPosition => "light position",
            Self::LightIntensity => "light intensity",
            Self::LightDirection => "light direction",
            Self::LightIrradiance => "light irradiance",
            Self::SpotCutoff => "spot light cutoff angle",
            Self::SpotBeamWidth => "spot light beam width",
            Self::BackgroundColor => "background colour",
            Self::SkyHorizon => "sky horizon colour",
            Self::SkyZenith => "sky zenith colour",
            Self::EnvironmentMap => "environment map",
            Self::EnvironmentScale => "environment map scale",
            Self::EnvironmentRotation => "environment map rotation",
            Self::Transform => "transform",
            Self::CameraFrom => "camera position",
            Self::CameraAt => "camera target",
            Self::CameraView => "camera view direction (from − at)",
            Self::CameraUp => "camera up vector",
            Self::CameraVfov => "camera field of view",
            Self::CameraAperture => "camera aperture radius",
            Self::CameraFocusDistance => "camera focus distance",
            Self::CameraEye => "camera eye",
            Self::ImageWidth => "image width",
            Self::ImageSize => "image size",
            Self::SamplesPerPixel => "samples per pixel",
            Self::MaxDepth => "max depth",
            Self::Exposure => "exposure",
            Self::Custom(name) => name,
        }
    }
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
