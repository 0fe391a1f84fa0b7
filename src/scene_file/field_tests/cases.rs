//! One file per field that its constructor refuses, and the key the error must be reported at.

use super::*;

const SPOT: &str =
    "[[lights]]\ntype = \"spot\"\nposition = [0, 2, 0]\ndirection = [0, -1, 0]\nintensity = [1, 1, 1]\n";

const MATTE: &str = "[materials.m]\ntype = \"lambertian\"\nalbedo = [0.5, 0.5, 0.5]\n";

/// A file that one constructor refuses, in `f64` unless `f32` is set: the field refused and
/// the key it must be reported at.
pub(super) struct Case {
    pub(super) text: String,
    pub(super) f32: bool,
    pub(super) field: Field,
    pub(super) at: &'static str,
}

fn object(kind: &str, keys: &str) -> String {
    format!("{MATTE}[[objects]]\ntype = \"{kind}\"\nmaterial = \"m\"\n{keys}\n")
}

pub(super) fn material(kind: &str, keys: &str) -> String {
    format!("[materials.x]\ntype = \"{kind}\"\n{keys}\n")
}

fn texture(kind: &str, keys: &str) -> String {
    format!("[textures.t]\ntype = \"{kind}\"\n{keys}\n")
}

fn look_at(keys: &str) -> String {
    let base = [
        ("from", "from = [0, 0, 0]"),
        ("at", "at = [0, 0, -1]"),
        ("vfov", "vfov = 40"),
        ("aspect", "aspect = 2"),
    ];
    let mut text = String::from("[camera]\ntype = \"look_at\"\n");
    for (name, line) in base {
        if !keys.contains(&format!("{name} =")) {
            text += line;
            text.push('\n');
        }
    }
    text + keys + "\n"
}

/// One case per field, named in a `match` without a catch-all: a new field without a
/// case here does not compile.
pub(super) fn case(field: Field) -> Option<Case> {
    let (text, f32, at): (String, bool, &str) = match field {
        Field::SphereCenter => (
            object("sphere", "center = [0, 0, inf]\nradius = 1"),
            false,
            "objects[0].center",
        ),
        Field::SphereRadius => (
            object("sphere", "center = [0, 0, -3]\nradius = 1e-60"),
            true,
            "objects[0].radius",
        ),
        Field::PlanePoint => (
            object("plane", "point = [nan, 0, 0]\nnormal = [0, 1, 0]"),
            false,
            "objects[0].point",
        ),
        Field::PlaneNormal => (
            object("plane", "point = [0, 0, 0]\nnormal = [0, 1e-50, 0]"),
            true,
            "objects[0].normal",
        ),
        Field::TriangleA => (
            object("triangle", "a = [-inf, 0, 0]\nb = [1, 0, 0]\nc = [0, 1, 0]"),
            false,
            "objects[0].a",
        ),
        Field::TriangleB => (
            object("triangle", "a = [0, 0, 0]\nb = [1e300, 0, 0]\nc = [0, 1, 0]"),
            true,
            "objects[0].b",
        ),
        Field::TriangleC => (
            object("triangle", "a = [0, 0, 0]\nb = [1, 0, 0]\nc = [0, nan, 0]"),
            false,
            "objects[0].c",
        ),
        Field::Triangle => (
            object("triangle", "a = [0, 0, 0]\nb = [1, 1, 1]\nc = [2, 2, 2]"),
            false,
            "objects[0]",
        ),
        Field::DiskCenter => (object("disk", "center = [0, 0, inf]"), false, "objects[0].center"),
        Field::DiskNormal => (
            object("disk", "normal = [0, 1e-50, 0]"),
            true,
            "objects[0].normal",
        ),
        Field::DiskRadius => (object("disk", "radius = 1e-60"), true, "objects[0].radius"),
        // Axes at an angle of 10⁻¹⁰: apart in f64, parallel within f32's rounding.
        Field::DiskAxes => (
            object("disk", "matrix = [[1, 1, 0, 0], [0, 1e-10, 0, 0], [0, 0, 1, -3]]"),
            true,
            "objects[0].matrix",
        ),
        // Moved where f32's step is 8: its x coordinates, ±1 about 10⁸, round to one value.
        Field::Mesh => (
            object("mesh", "file = \"meshes/rectangle.obj\"\ntranslate = [1e8, 0, 0]"),
            true,
            "objects[0].file",
        ),
        Field::MirrorAlbedo => (
            material("mirror", "albedo = [1.5, 0, 0]"),
            false,
            "materials.x.albedo",
        ),
        Field::MatteAlbedo => (
            material("lambertian", "albedo = [0, -0.5, 0]"),
            false,
            "materials.x.albedo",
        ),
        Field::RefractiveIndex => (material("dielectric", "index = 1e-50"), true, "materials.x.index"),
        Field::DielectricAlbedo => (
            material("dielectric", "index = 1.5\nalbedo = [0, 0, 2]"),
            false,
            "materials.x.albedo",
        ),
        Field::EmittedRadiance => (
            material("emissive", "radiance = [1e300, 1, 1]"),
            true,
            "materials.x.radiance",
        ),
        Field::EmissiveAlbedo => (
            material("emissive", "radiance = [1, 1, 1]\nalbedo = [nan, 0, 0]"),
            false,
            "materials.x.albedo",
        ),
        Field::CheckerboardColor0 => (
            texture("checkerboard", "color0 = [nan, 0, 0]"),
            false,
            "textures.t.color0",
        ),
        Field::CheckerboardColor1 => (
            texture("checkerboard", "color1 = [0, 1e39, 0]"),
            true,
            "textures.t.color1",
        ),
        Field::TextureScale => (
            texture("checkerboard", "scale = [1, inf]"),
            false,
            "textures.t.scale",
        ),
        Field::TextureOffset => (
            texture("checkerboard", "offset = [1e39, 0]"),
            true,
            "textures.t.offset",
        ),
        Field::ConductorEta => (
            material("conductor", "eta = [-1, 0, 0]"),
            false,
            "materials.x.eta",
        ),
        Field::ConductorK => (
            material("rough_conductor", "k = [0, nan, 0]"),
            false,
            "materials.x.k",
        ),
        Field::ConductorName => (
            material("conductor", "material = \"Fe\""),
            false,
            "materials.x.material",
        ),
        Field::SpecularReflectance => (
            material(
                "conductor",
                "material = \"Au\"\nspecular_reflectance = [1.5, 0, 0]",
            ),
            false,
            "materials.x.specular_reflectance",
        ),
        Field::SpecularTransmittance => (
            material("rough_dielectric", "specular_transmittance = [0, 0, -1]"),
            false,
            "materials.x.specular_transmittance",
        ),
        Field::DiffuseReflectance => (
            material("plastic", "diffuse_reflectance = [2, 0, 0]"),
            false,
            "materials.x.diffuse_reflectance",
        ),
        Field::Alpha => (
            material("rough_conductor", "alpha = 1e-50"),
            true,
            "materials.x.alpha",
        ),
        Field::AlphaU => (
            material("rough_conductor", "alpha_u = 0\nalpha_v = 0.1"),
            false,
            "materials.x.alpha_u",
        ),
        Field::AlphaV => (
            material("rough_dielectric", "alpha_u = 0.1\nalpha_v = nan"),
            false,
            "materials.x.alpha_v",
        ),
        Field::InteriorIndex => (
            material("thin_dielectric", "int_ior = \"unobtainium\""),
            false,
            "materials.x.int_ior",
        ),
        Field::ExteriorIndex => (
            material("rough_plastic", "ext_ior = 1e-60"),
            true,
            "materials.x.ext_ior",
        ),
        Field::TwoSidedFront => (
            material("two_sided", "front = { type = \"dielectric\", index = 1.5 }"),
            false,
            "materials.x.front",
        ),
        Field::TwoSidedBack => (
            material(
                "two_sided",
                "front = { type = \"plastic\" }\nback = { type = \"emissive\", radiance = [1, 1, 1] }",
            ),
            false,
            "materials.x.back",
        ),
        Field::LightPosition => (
            "[[lights]]\nposition = [1e39, 0, 0]\nintensity = [1, 1, 1]\n".into(),
            true,
            "lights[0].position",
        ),
        Field::LightIntensity => (
            "[[lights]]\nposition = [0, 0, 0]\nintensity = [1, -1, 1]\n".into(),
            false,
            "lights[0].intensity",
        ),
        Field::LightDirection => (
            "[[lights]]\ntype = \"directional\"\ndirection = [0, -1e-50, 0]\nirradiance = [1, 1, 1]\n".into(),
            true,
            "lights[0].direction",
        ),
        Field::LightIrradiance => (
            "[[lights]]\ntype = \"directional\"\ndirection = [0, -1, 0]\nirradiance = [nan, 1, 1]\n".into(),
            false,
            "lights[0].irradiance",
        ),
        Field::SpotCutoff => (
            format!("{SPOT}cutoff_angle = 91\n"),
            false,
            "lights[0].cutoff_angle",
        ),
        Field::SpotBeamWidth => (
            format!("{SPOT}cutoff_angle = 30\nbeam_width = 40\n"),
            false,
            "lights[0].beam_width",
        ),
        Field::BackgroundColor => (
            "[background]\ntype = \"solid\"\ncolor = [0, 0, -1]\n".into(),
            false,
            "background.color",
        ),
        Field::SkyHorizon => (
            "[background]\ntype = \"sky\"\nhorizon = [inf, 0, 0]\n".into(),
            false,
            "background.horizon",
        ),
        Field::SkyZenith => (
            "[background]\ntype = \"sky\"\nzenith = [0, 1e40, 0]\n".into(),
            true,
            "background.zenith",
        ),
        Field::EnvironmentMap => (
            "[background]\ntype = \"envmap\"\nfile = \"no-such-map.exr\"\n".into(),
            false,
            "background.file",
        ),
        Field::EnvironmentScale => (
            "[background]\ntype = \"envmap\"\nfile = \"textures/sky.hdr\"\nscale = -1\n".into(),
            false,
            "background.scale",
        ),
        // Rotations in degrees are always a rotation: no file can give another matrix.
        Field::EnvironmentRotation => return None,
        // Scale, rotate and translate always make an invertible transform (a zero scale is
        // refused as a scale).
        Field::Transform => return None,
        Field::CameraFrom => (look_at("from = [0, inf, 0]"), false, "camera.from"),
        Field::CameraAt => (look_at("at = [0, 0, 1e39]"), true, "camera.at"),
        Field::CameraView => (look_at("from = [1, 2, 3]\nat = [1, 2, 3]"), false, "camera.at"),
        Field::CameraUp => (look_at("up = [0, 0, -1]"), false, "camera.up"),
        Field::CameraVfov => (look_at("vfov = 180"), false, "camera.vfov"),
        Field::CameraAperture => (look_at("aperture = -0.1"), false, "camera.aperture"),
        Field::CameraFocusDistance => (
            look_at("aperture = 0.1\nfocus_distance = 1e-50"),
            true,
            "camera.focus_distance",
        ),
        Field::CameraEye => (
            "[camera]\ntype = \"screen\"\neye = [nan, 0, 0]\n".into(),
            false,
            "camera.eye",
        ),
        Field::ImageWidth => ("[render]\nwidth = 41\n".into(), false, "render.width"),
        Field::ImageSize => (
            format!("[render]\nwidth = 1\n{}", look_at("")),
            false,
            "render.width",
        ),
        Field::SamplesPerPixel => ("[render]\nspp = 0\n".into(), false, "render.spp"),
        Field::MaxDepth => ("[render]\nmax_depth = 1001\n".into(), false, "render.max_depth"),
        Field::Exposure => ("[render]\nexposure = -inf\n".into(), false, "render.exposure"),
        // A user's own type: no scene file builds one.
        Field::Custom(_) => return None,
    };
    Some(Case { text, f32, field, at })
}
