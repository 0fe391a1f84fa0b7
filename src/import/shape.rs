//! Mitsuba 3's `<shape>` plugins as objects: meshes (`obj`, `ply`, placed by any map),
//! spheres, disks, the unit `rectangle` and `cube` as triangles, and `shapegroup`s (of
//! those) placed by `instance`s. A shape's `<bsdf>` names its material; an `area` emitter
//! makes it emissive.

use super::convert::Importer;
use super::xml::Plugin;
use crate::error::Result;
use crate::scene_file::{MaterialSpec, MeshDef, ObjectSpec, TextureRef};
use crate::transform::Affine;

impl Importer {
    pub(super) fn shape(&mut self, s: &Plugin) -> Result<()> {
        match s.kind.as_str() {
            "shapegroup" => return self.shapegroup(s),
            "instance" => return self.instance(s),
            _ => {}
        }
        self.read(s);
        let bsdf = s.children.iter().find(|c| c.tag == "bsdf");
        let area = s.children.iter().find(|c| c.tag == "emitter");
        let material = match (area, bsdf) {
            (Some(e), _) if e.kind != "area" => return Err(self.unsupported(e, &e.kind)),
            (Some(e), b) => {
                self.read(e);
                self.lights_on_surfaces = true;
                let albedo = match b {
                    Some(b) if b.kind == "diffuse" => match self.texture(b, "reflectance")? {
                        Some(TextureRef::Color(c)) => Some(c),
                        None => Some([0.5; 3]),
                        Some(_) => {
                            return Err(b
                                .at
                                .error("an emitter's diffuse reflectance is a colour here, not a texture"));
                        }
                    },
                    Some(b) => {
                        self.warn(
                            b,
                            "under an area emitter it reflects nothing here (only a diffuse one does)".into(),
                        );
                        None
                    }
                    // Mitsuba gives an emitter without a BSDF a black one (a shape without
                    // either a diffuse of 0.5): found by validate/foreign's point cloud,
                    // whose lamp lit its floor a second time here.
                    None => None,
                };
                let name = format!("area_line{}", e.at.line);
                let radiance = self.triple(e, "radiance")?.unwrap_or([1.0; 3]);
                self.file.materials.insert(
                    name.clone(),
                    MaterialSpec::Emissive {
                        radiance,
                        two_sided: false,
                        albedo,
                    },
                );
                name
            }
            (None, Some(b)) => self.named_material(b)?,
            (None, None) => {
                let name = "default_diffuse".to_string();
                self.file
                    .materials
                    .entry(name.clone())
                    .or_insert(MaterialSpec::Lambertian {
                        albedo: TextureRef::Color([0.5; 3]),
                    });
                name
            }
        };
        let m = self.to_world(s)?;
        match s.kind.as_str() {
            "obj" | "ply" => {
                let file = self
                    .text(s, "filename")?
                    .ok_or_else(|| s.at.error(format!("{}: needs a `filename`", s.label())))?;
                let placed = self.placed(s)?;
                let face_normals = self.boolean(s, "face_normals")?.unwrap_or(false);
                let mut flip_tex_coords = self.boolean(s, "flip_tex_coords")?;
                // A file without normals: Mitsuba's smooth ones, held in memory under a name
                // whose extension is no longer the file's (so its uv convention is set here).
                let smooth = if face_normals {
                    None
                } else {
                    self.smooth_mesh(&file, &m)
                };
                let key = match smooth {
                    Some(name) => {
                        let flips = crate::mesh::flips_tex_coords(&self.located(&file));
                        flip_tex_coords = Some(flip_tex_coords.unwrap_or(flips));
                        name
                    }
                    None => self.path_of(&file),
                };
                self.file.objects.push(ObjectSpec::Mesh {
                    file: key,
                    scale: placed.scale,
                    rotate: placed.rotate,
                    translate: placed.translate,
                    material,
                    face_normals,
                    flip_tex_coords,
                    matrix: placed.matrix,
                });
            }
            "raytrace_plane" | "raytrace_triangle" => self.flat_shape(s, material)?,
            _ => self.unit_shape(s, material, &m)?,
        }
        Ok(())
    }

    /// A `sphere`, `disk`, `rectangle` or `cube` placed by `m` (its `to_world`, or that
    /// then an instance's).
    fn unit_shape(&mut self, s: &Plugin, material: String, m: &Affine) -> Result<()> {
        match s.kind.as_str() {
            "sphere" => {
                let c = self.triple(s, "center")?.unwrap_or([0.0; 3]);
                let radius = self.number(s, "radius")?.unwrap_or(1.0);
                let scale = uniform_scale(m).ok_or_else(|| {
                    s.at.error("sphere: `to_world` may only scale uniformly, turn and move it")
                })?;
                self.file.objects.push(ObjectSpec::Sphere {
                    center: m.point(c),
                    radius: radius * scale,
                    material,
                });
            }
            "disk" => {
                // `flip_normals` turns the unit disk over first: Mitsuba's `to_world·scale(1, 1, −1)`.
                let m = match self.boolean(s, "flip_normals")? {
                    Some(true) => Affine::scale([1.0, 1.0, -1.0]).then(m),
                    _ => *m,
                };
                self.file.objects.push(ObjectSpec::Disk {
                    center: [0.0; 3],
                    normal: [0.0, 0.0, 1.0],
                    radius: 1.0,
                    matrix: (m != Affine::IDENTITY).then(|| m.rows()),
                    material,
                });
            }
            "rectangle" | "cube" => {
                self.unit_shape_uv(s, &material);
                let corners: &[[[f64; 3]; 3]] = if s.kind == "rectangle" { &RECTANGLE } else { &CUBE };
                for [a, b, c] in corners {
                    let (a, b, c) = (m.point(*a), m.point(*b), m.point(*c));
                    self.file.objects.push(ObjectSpec::Triangle {
                        a,
                        b,
                        c,
                        material: material.clone(),
                    });
                }
            }
            other => return Err(self.unsupported(s, other)),
        }
        Ok(())
    }
}

/// A shape of a `shapegroup`, placed by each `instance` of it.
#[derive(Clone)]
pub(super) enum Part {
    /// An `obj` or `ply`: its `[meshes]` name, its own map, its material.
    Mesh(String, Affine, String),
    /// A `sphere`, `disk`, `rectangle` or `cube` and its material, made anew for each
    /// instance (an instance of a sphere is a sphere).
    Unit(Box<Plugin>, String),
}

impl Importer {
    /// A `shapegroup` of `obj` and `ply` shapes (each a `[meshes]` entry) and unit shapes,
    /// placed only by the `instance`s that name the group.
    fn shapegroup(&mut self, g: &Plugin) -> Result<()> {
        self.read(g);
        let id =
            g.id.clone()
                .ok_or_else(|| g.at.error("a <shape type=\"shapegroup\"> needs an `id`"))?;
        let mut parts = Vec::new();
        for (k, s) in g.children.iter().enumerate() {
            self.read(s);
            const UNIT: [&str; 4] = ["sphere", "disk", "rectangle", "cube"];
            let mesh = matches!(s.kind.as_str(), "obj" | "ply");
            if s.tag != "shape" || !(mesh || UNIT.contains(&s.kind.as_str())) {
                return Err(s.at.error(format!(
                    "{}: a shapegroup here holds obj, ply, sphere, disk, rectangle and cube shapes",
                    s.label()
                )));
            }
            if s.children.iter().any(|c| c.tag == "emitter") {
                return Err(s
                    .at
                    .error("an instanced shape is not sampled as a light here: no emitter on it"));
            }
            let material = match s.children.iter().find(|c| c.tag == "bsdf") {
                Some(b) => self.named_material(b)?,
                None => self.default_material(),
            };
            if !mesh {
                parts.push(Part::Unit(Box::new(s.clone()), material));
                continue;
            }
            let file = self
                .text(s, "filename")?
                .ok_or_else(|| s.at.error(format!("{}: needs a `filename`", s.label())))?;
            self.instance_normals(s)?;
            let name = format!("{id}_{k}");
            self.file.meshes.insert(
                name.clone(),
                MeshDef {
                    file: self.path_of(&file),
                },
            );
            parts.push(Part::Mesh(name, self.to_world(s)?, material));
        }
        self.groups.insert(id, parts);
        Ok(())
    }

    /// An `instance` of a `shapegroup`: each of its meshes placed by its own map, then the
    /// instance's. (An instance shades with its faces' normals: see the scene format.)
    fn instance(&mut self, i: &Plugin) -> Result<()> {
        self.read(i);
        let Some(group) = i
            .children
            .iter()
            .find(|c| c.kind == "shapegroup")
            .and_then(|g| g.id.as_ref())
        else {
            return Err(i
                .at
                .error("an <shape type=\"instance\"> names its shapegroup by a <ref>"));
        };
        let parts = self
            .groups
            .get(group)
            .cloned()
            .ok_or_else(|| i.at.error(format!("no shapegroup `{group}`")))?;
        let to_world = self.to_world(i)?;
        for part in parts {
            match part {
                Part::Mesh(mesh, own, material) => self.file.objects.push(ObjectSpec::Instance {
                    mesh,
                    scale: Default::default(),
                    rotate: [0.0; 3],
                    translate: [0.0; 3],
                    matrix: Some(own.then(&to_world).rows()),
                    material,
                }),
                Part::Unit(s, material) => {
                    let m = self.to_world(&s)?.then(&to_world);
                    self.unit_shape(&s, material, &m)?;
                }
            }
        }
        Ok(())
    }

    fn default_material(&mut self) -> String {
        let name = "default_diffuse".to_string();
        self.file
            .materials
            .entry(name.clone())
            .or_insert(MaterialSpec::Lambertian {
                albedo: TextureRef::Color([0.5; 3]),
            });
        name
    }
}

/// Mitsuba's `rectangle`: `[−1, 1]²` at `z = 0`, facing `+z`.
const RECTANGLE: [[[f64; 3]; 3]; 2] = [
    [[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0]],
    [[-1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]],
];

/// Mitsuba's `cube`: `[−1, 1]³`, every face wound outward.
const CUBE: [[[f64; 3]; 3]; 12] = {
    const fn face(axis: usize, sign: f64) -> [[[f64; 3]; 3]; 2] {
        // The two other axes, in the order that makes (u × v) point along +axis.
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        let mut q = [[0.0; 3]; 4];
        let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
        let mut k = 0;
        while k < 4 {
            q[k][axis] = sign;
            q[k][u] = corners[k].0 * sign;
            q[k][v] = corners[k].1;
            k += 1;
        }
        [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]
    }
    let mut all = [[[0.0; 3]; 3]; 12];
    let mut f = 0;
    while f < 6 {
        let two = face(f / 2, if f % 2 == 0 { 1.0 } else { -1.0 });
        all[2 * f] = two[0];
        all[2 * f + 1] = two[1];
        f += 1;
    }
    all
};

/// The factor of a map that scales uniformly (then turns and moves), if it does.
pub(super) fn uniform_scale(m: &Affine) -> Option<f64> {
    let r = m.rows();
    let col = |j: usize| (r[0][j] * r[0][j] + r[1][j] * r[1][j] + r[2][j] * r[2][j]).sqrt();
    let s = col(0);
    let dot = |i: usize, j: usize| r[0][i] * r[0][j] + r[1][i] * r[1][j] + r[2][i] * r[2][j];
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * s.max(1.0);
    (close(col(1), s)
        && close(col(2), s)
        && close(dot(0, 1), 0.0)
        && close(dot(1, 2), 0.0)
        && close(dot(0, 2), 0.0))
    .then_some(s)
}
