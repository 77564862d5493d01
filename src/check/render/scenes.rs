//! The scenes the renderer's checks are made of, built in code. Chapter: *Testing the
//! renderer* (`chapters/renderer/testing.md`).
//!
//! Each is small (a few dozen pixels on a side) and chosen for what it exposes:
//!
//! * a Lambertian floor under a large, close parallelogram light ([`floor_under_quad`]),
//!   under a sphere light ([`floor_under_sphere`]) and under both at once
//!   ([`floor_under_two_lights`]): one bounce of direct light, where light sampling and
//!   BSDF sampling have comparable densities, so that every weight of multiple importance
//!   sampling and the choice between two lights matter. Their expected images are the
//!   closed forms of the shadow-ray chapter.
//! * a glass sphere, a mirror sphere and a thin film in a sky whose radiance changes with
//!   direction ([`glass_in_sky`], [`mirror_in_sky`], [`film_in_sky`]): only delta bounces,
//!   whose expected images a deterministic splitting of every Fresnel branch computes.
//! * scenes with sharp edges across pixels, whose every pixel has a closed form
//!   ([`super::edges`]): a blackbody and a fluorescent light seen directly against black
//!   ([`lights_seen_directly`]), a red Lambertian quad in a constant sky
//!   ([`coloured_quad_in_sky`]), and the shadows that one black rectangle casts from two
//!   small lights of different colours on the floor ([`shadows_of_two_lights`]). The
//!   lights' and the quad's edges are turned against the pixel grid, so that the pixels
//!   along an edge are covered in many shares; the shadows' penumbrae spread theirs.
//!   (The shadow scene's occluder hides lights from the floor, unlike every other
//!   direct-light scene; its expected image accounts for it.)
//! * one scene with everything ([`everything`]): diffuse walls, glass, a mirror, a
//!   dispersive sphere, a thin film, two lights and a sky, for the comparisons of the
//!   estimators with one another.
//!
//! No shape of the other direct-light scenes hides a light from the floor, and every light lies
//! above the floor's horizon: the closed forms hold as they are (the expected image
//! checks both, [`super::exact()`]).

use glam::DVec3;

use crate::geometry::parallelogram::Parallelogram;
use crate::geometry::sphere::Sphere;
use crate::optics::dispersion;
use crate::render::scene::{
    CameraSpec, DirectLight, Emitter, Environment, Geometry, Ior, LightSampling, LightShape,
    Material, RenderSettings, Scene, Shape, Thickness, Wavelength,
};
use crate::spectral::spectrum::{Spectrum, Table, builtin};
use crate::spectral::wavelength::WavelengthStrategy;
use crate::transport::shadow::{Heuristic, QuadLight, SphereLight};

/// The settings of every check scene: `spp` samples, seed `seed`, hero-visible
/// wavelengths, MIS with the power heuristic, roulette from depth 3.
pub fn settings(spp: u32, seed: u64) -> RenderSettings {
    RenderSettings {
        spp,
        seed,
        wavelengths: Wavelength::Strategy(WavelengthStrategy::HeroVisible),
        direct: DirectLight::Mis(Heuristic::Power),
        roulette_depth: 3,
        light_sampling: LightSampling::Area,
        max_depth: 1000,
    }
}

/// A reflectance rising linearly from 0.2 at 360 nm to 0.8 at 830 nm (a warm white).
pub(crate) fn floor_reflectance() -> Spectrum {
    match Table::new(vec![360.0, 830.0], vec![0.2, 0.8]) {
        Ok(t) => Spectrum::Table(t),
        Err(e) => unreachable!("a valid two-knot table: {e}"),
    }
}

/// The quad light's spectrum: a 5000 K blackbody with peak 2 (smooth: the estimate's
/// noise is that of the light transport, not of the wavelengths).
pub(crate) fn daylight_blackbody() -> Spectrum {
    Spectrum::Blackbody {
        kelvin: 5000.0,
        peak: 2.0,
    }
}

/// The spectrum of the fluorescent variant of the quad light: CIE F11, a three-band lamp
/// (narrow peaks, where wavelength sampling matters most), scaled to a peak near 2.
pub fn fluorescent() -> Spectrum {
    Spectrum::Table(builtin("cie_illuminant_F11.csv").scaled(0.03))
}

/// The sphere light's spectrum: a 2700 K blackbody with peak 4.
pub(crate) fn warm_blackbody() -> Spectrum {
    Spectrum::Blackbody {
        kelvin: 2700.0,
        peak: 4.0,
    }
}

fn quad(corner: [f64; 3], e1: [f64; 3], e2: [f64; 3]) -> Parallelogram {
    match Parallelogram::new(
        DVec3::from_array(corner),
        DVec3::from_array(e1),
        DVec3::from_array(e2),
    ) {
        Ok(p) => p,
        Err(e) => unreachable!("a valid parallelogram: {e}"),
    }
}

/// The floor: a Lambertian 6 x 6 square at `y = 0`, centred on the origin.
fn floor() -> Shape {
    Shape {
        geometry: Geometry::Quad(quad([-3.0, 0.0, -3.0], [6.0, 0.0, 0.0], [0.0, 0.0, 6.0])),
        material: 0,
    }
}

/// The quad light: 1 x 0.8 at height 1.2, emitting downwards (`e1 x e2 = -y`).
fn quad_light() -> Emitter {
    match QuadLight::new(
        DVec3::new(-0.5, 1.2, -0.3),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 0.0, 0.8),
    ) {
        Ok(q) => Emitter::new(LightShape::Quad(q), daylight_blackbody()),
        Err(e) => unreachable!("a valid light: {e}"),
    }
}

/// The sphere light: radius 0.25 at `(1.3, 1.7, 0.9)`, above the quad light's plane (so it
/// never hides the quad) and beside it (so the quad hides it from no point the camera sees).
fn sphere_light() -> Emitter {
    match SphereLight::new(DVec3::new(1.3, 1.7, 0.9), 0.25) {
        Ok(s) => Emitter::new(LightShape::Sphere(s), warm_blackbody()),
        Err(e) => unreachable!("a valid light: {e}"),
    }
}

/// The camera of the floor scenes: from `(0, 0.8, -1.4)` down towards `(0, 0, 0.3)`, 40°,
/// `side x side` pixels: the floor fills all but the top rows, the lights are out of view.
fn floor_camera(side: u32) -> CameraSpec {
    CameraSpec {
        position: DVec3::new(0.0, 0.8, -1.4),
        look_at: DVec3::new(0.0, 0.0, 0.3),
        up: DVec3::Y,
        fov_y_deg: 40.0,
        width: side,
        height: side,
    }
}

fn floor_scene(side: u32, spp: u32, lights: Vec<Emitter>) -> Scene {
    Scene {
        camera: floor_camera(side),
        settings: settings(spp, 1),
        materials: vec![Material::Lambert {
            reflectance: floor_reflectance(),
        }],
        shapes: vec![floor()],
        lights,
        environment: None,
        hash: 0,
        files: Vec::new(),
    }
}

/// A Lambertian floor under the quad light.
pub fn floor_under_quad(side: u32, spp: u32) -> Scene {
    floor_scene(side, spp, vec![quad_light()])
}

/// A Lambertian floor under the quad light with the fluorescent spectrum, its wavelengths
/// drawn by `wavelengths`.
pub(crate) fn floor_under_fluorescent(side: u32, spp: u32, wavelengths: Wavelength) -> Scene {
    let mut light = quad_light();
    light.emission = fluorescent();
    let mut s = floor_scene(side, spp, vec![light]);
    s.settings.wavelengths = wavelengths;
    s
}

/// A Lambertian floor under the sphere light.
pub fn floor_under_sphere(side: u32, spp: u32) -> Scene {
    floor_scene(side, spp, vec![sphere_light()])
}

/// A Lambertian floor under the sphere light and the quad light turned over, emitting
/// upwards: the floor sees only the quad's back, which emits nothing, so the image is the
/// sphere light's alone; a renderer that lets a one-sided light shine from its back lights
/// the floor twice over.
pub(crate) fn floor_under_a_light_turned_away(side: u32, spp: u32) -> Scene {
    // On the far side of the floor from the sphere light, so that it hides the sphere
    // light from no point of the floor.
    match QuadLight::new(
        DVec3::new(-1.6, 1.2, 0.5),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 0.0, -0.8),
    ) {
        Ok(q) => floor_scene(
            side,
            spp,
            vec![
                Emitter::new(LightShape::Quad(q), daylight_blackbody()),
                sphere_light(),
            ],
        ),
        Err(e) => unreachable!("a valid light: {e}"),
    }
}

/// A Lambertian floor under both lights (different spectra): the renderer picks one per
/// shadow ray, and its multiple importance sampling must count the pick.
pub fn floor_under_two_lights(side: u32, spp: u32) -> Scene {
    floor_scene(side, spp, vec![quad_light(), sphere_light()])
}

/// The sky of the delta scenes: daylight (D65) behind the objects (towards `+z`, away
/// from the camera), a dim 1800 K glow towards the camera, blended linearly. Light that
/// passes through glass or a film then comes from the bright side and light they reflect
/// from the dim one, so every mistake in choosing between the two changes the image.
pub fn sky() -> Environment {
    Environment::Gradient {
        axis: DVec3::Z,
        above: Spectrum::Table(builtin("cie_illuminant_D65.csv").scaled(0.01)),
        below: Spectrum::Blackbody {
            kelvin: 1800.0,
            peak: 0.1,
        },
    }
}

/// The camera of the delta scenes: from `(0, 0, -1.6)` at the origin, 40° (the ball fills
/// most of the view), a little tilted so that up is not the image's vertical.
fn sky_camera(side: u32) -> CameraSpec {
    CameraSpec {
        position: DVec3::new(0.0, 0.0, -1.6),
        look_at: DVec3::ZERO,
        up: DVec3::new(0.15, 1.0, 0.0),
        fov_y_deg: 40.0,
        width: side,
        height: side,
    }
}

fn sky_scene(side: u32, spp: u32, material: Material, geometry: Geometry) -> Scene {
    Scene {
        camera: sky_camera(side),
        settings: settings(spp, 1),
        materials: vec![material],
        shapes: vec![Shape {
            geometry,
            material: 0,
        }],
        lights: Vec::new(),
        environment: Some(sky()),
        hash: 0,
        files: Vec::new(),
    }
}

/// The ball of the delta scenes: radius 0.5 at the origin.
fn ball() -> Geometry {
    Geometry::Sphere(Sphere::new(DVec3::ZERO, 0.5))
}

/// A glass sphere (index 1.5) in the sky.
pub fn glass_in_sky(side: u32, spp: u32) -> Scene {
    sky_scene(
        side,
        spp,
        Material::Dielectric {
            ior: Ior::Constant(1.5),
        },
        ball(),
    )
}

/// A mirror sphere in the sky.
pub fn mirror_in_sky(side: u32, spp: u32) -> Scene {
    sky_scene(side, spp, Material::Mirror, ball())
}

/// A soap film (index 1.33, 200 nm at the bottom to 900 nm at the top) across the view,
/// turned 35° about the vertical so that it reflects the sky beside the camera.
pub fn film_in_sky(side: u32, spp: u32) -> Scene {
    let (c, s) = (35f64.to_radians().cos(), 35f64.to_radians().sin());
    let half = DVec3::new(c, 0.0, s);
    let corner = -1.2 * half - DVec3::new(0.0, 0.7, 0.0);
    sky_scene(
        side,
        spp,
        Material::ThinFilm {
            ior: 1.33,
            thickness: Thickness {
                bottom_nm: 200.0,
                top_nm: 900.0,
                y: [-0.7, 0.7],
            },
        },
        Geometry::Quad(quad(
            corner.to_array(),
            (2.4 * half).to_array(),
            [0.0, 1.4, 0.0],
        )),
    )
}

/// A light: the parallelogram from `corner` along `e1` and `e2` (emitting towards
/// `e1 x e2`) with the spectrum `emission`.
fn quad_emitter(corner: [f64; 3], e1: [f64; 3], e2: [f64; 3], emission: Spectrum) -> Emitter {
    match QuadLight::new(
        DVec3::from_array(corner),
        DVec3::from_array(e1),
        DVec3::from_array(e2),
    ) {
        Ok(q) => Emitter::new(LightShape::Quad(q), emission),
        Err(e) => unreachable!("a valid light: {e}"),
    }
}

/// Two parallelogram lights in the plane `z = 0`, facing the camera of the delta scenes,
/// seen directly against black: a 5000 K blackbody at `-x` (the image's right: the
/// camera's right is `-x`), the three-band fluorescent spectrum ([`fluorescent`]), whose
/// colour depends on which wavelengths a pixel's samples draw, at `+x`. Their edges are
/// turned against the pixel grid (14 to 27 degrees from the image's rows and columns,
/// with the camera's roll), so that the pixels along an edge are covered in many shares. Every pixel's
/// expected value is its covered share of each light's colour ([`super::edges::flat`]).
pub fn lights_seen_directly(side: u32, spp: u32) -> Scene {
    Scene {
        camera: sky_camera(side),
        settings: settings(spp, 1),
        materials: Vec::new(),
        shapes: Vec::new(),
        lights: vec![
            // e1 x e2 = -z: towards the camera.
            quad_emitter(
                [-0.4, -0.33, 0.0],
                [-0.12, 0.65, 0.0],
                [0.3, 0.1, 0.0],
                daylight_blackbody(),
            ),
            quad_emitter(
                [0.1, -0.4, 0.0],
                [-0.08, 0.75, 0.0],
                [0.4, 0.06, 0.0],
                fluorescent(),
            ),
        ],
        environment: None,
        hash: 0,
        files: Vec::new(),
    }
}

/// A reflectance that steps from 0.05 below 570 nm to 0.85 above 610 nm: a saturated
/// red, whose colour depends on which wavelengths a pixel's samples draw.
pub fn red_reflectance() -> Spectrum {
    match Table::new(
        vec![360.0, 570.0, 610.0, 830.0],
        vec![0.05, 0.05, 0.85, 0.85],
    ) {
        Ok(t) => Spectrum::Table(t),
        Err(e) => unreachable!("a valid table: {e}"),
    }
}

/// A red Lambertian parallelogram ([`red_reflectance`]), its edges turned against the
/// pixel grid,
/// in a constant sky of daylight (D65, about 1): its radiance is `rho(lambda)
/// L(lambda)`, since it sees nothing but the sky, and the sky's around it. An edge pixel
/// mixes the two by its covered share ([`super::edges::flat`]); a pixel whose wavelengths
/// depend on the point in it gets the wrong colour there. One wavelength per path (visible
/// pdf): the hero's four lanes, a quarter of the wavelengths' numbers apart, cover every
/// wavelength equally from any range of numbers a quarter long, so a hero estimate hardly
/// sees that mistake.
pub fn coloured_quad_in_sky(side: u32, spp: u32) -> Scene {
    let mut settings = settings(spp, 1);
    settings.wavelengths = Wavelength::Strategy(WavelengthStrategy::Visible);
    Scene {
        camera: sky_camera(side),
        settings,
        materials: vec![Material::Lambert {
            reflectance: red_reflectance(),
        }],
        shapes: vec![Shape {
            // A diamond whose four edges are 20 to 40 degrees from the image's vertical: at
            // every edge the part of a pixel covered depends on the point's x.
            geometry: Geometry::Quad(quad(
                [-0.35, -0.1, 0.3],
                [0.3, 0.55, 0.0],
                [0.3, -0.5, 0.05],
            )),
            material: 0,
        }],
        lights: Vec::new(),
        environment: Some(Environment::Constant(Spectrum::Table(
            builtin("cie_illuminant_D65.csv").scaled(0.01),
        ))),
        hash: 0,
        files: Vec::new(),
    }
}

/// The floor (24 x 24, so that it fills the view) under two small lights facing down, a
/// 5000 K one (peak 30) 0.2 x 0.2 at height 1.2 and a 2700 K one (peak 40) 0.2 x 0.2 at
/// height 1.3, with a
/// black 0.3 x 0.3 rectangle at height 0.5 between: two shadows of different colours, each
/// with a penumbra a few pixels wide, overlapping in part. The light chosen for a shadow
/// ray and the point on it both matter at every shadow's edge
/// ([`super::edges::shadow`]).
pub fn shadows_of_two_lights(side: u32, spp: u32) -> Scene {
    let black = Spectrum::Constant(0.0);
    Scene {
        camera: floor_camera(side),
        settings: settings(spp, 1),
        materials: vec![
            Material::Lambert {
                reflectance: floor_reflectance(),
            },
            Material::Lambert { reflectance: black },
        ],
        shapes: vec![
            Shape {
                geometry: Geometry::Quad(quad(
                    [-12.0, 0.0, -4.0],
                    [24.0, 0.0, 0.0],
                    [0.0, 0.0, 24.0],
                )),
                material: 0,
            },
            Shape {
                geometry: Geometry::Quad(quad([-0.1, 0.5, 0.3], [0.3, 0.0, 0.0], [0.0, 0.0, 0.3])),
                material: 1,
            },
        ],
        lights: vec![
            // e1 x e2 = x x z = -y: down.
            quad_emitter(
                [-0.3, 1.2, 0.0],
                [0.2, 0.0, 0.0],
                [0.0, 0.0, 0.2],
                Spectrum::Blackbody {
                    kelvin: 5000.0,
                    peak: 30.0,
                },
            ),
            quad_emitter(
                [0.25, 1.3, 0.1],
                [0.2, 0.0, 0.0],
                [0.0, 0.0, 0.2],
                Spectrum::Blackbody {
                    kelvin: 2700.0,
                    peak: 40.0,
                },
            ),
        ],
        environment: None,
        hash: 0,
        files: Vec::new(),
    }
}

/// Everything at once, for the comparisons of estimators: a diffuse floor and back wall,
/// a glass sphere, a mirror sphere, a dispersive (N-BK7) sphere and a thin film in front of
/// the wall, the two lights, and the sky.
pub fn everything(side: u32, spp: u32) -> Scene {
    let sphere = |x: f64, z: f64, r: f64, material: usize| Shape {
        geometry: Geometry::Sphere(Sphere::new(DVec3::new(x, r, z), r)),
        material,
    };
    Scene {
        camera: CameraSpec {
            position: DVec3::new(0.0, 1.0, -2.6),
            look_at: DVec3::new(0.0, 0.45, 0.5),
            up: DVec3::Y,
            fov_y_deg: 45.0,
            width: side,
            height: side,
        },
        settings: settings(spp, 1),
        materials: vec![
            Material::Lambert {
                reflectance: floor_reflectance(),
            },
            Material::Dielectric {
                ior: Ior::Constant(1.5),
            },
            Material::Mirror,
            Material::Dielectric {
                ior: Ior::Sellmeier(dispersion::material(dispersion::N_BK7)),
            },
            Material::ThinFilm {
                ior: 1.33,
                thickness: Thickness {
                    bottom_nm: 250.0,
                    top_nm: 700.0,
                    y: [0.0, 1.0],
                },
            },
        ],
        shapes: vec![
            floor(),
            Shape {
                geometry: Geometry::Quad(quad([-3.0, 0.0, 1.5], [6.0, 0.0, 0.0], [0.0, 3.0, 0.0])),
                material: 0,
            },
            sphere(-0.9, 0.3, 0.35, 1),
            sphere(0.0, 0.7, 0.35, 2),
            sphere(0.9, 0.3, 0.35, 3),
            Shape {
                geometry: Geometry::Quad(quad([-0.6, 0.0, 1.2], [1.2, 0.0, -0.2], [0.0, 1.0, 0.0])),
                material: 4,
            },
        ],
        lights: vec![quad_light(), sphere_light()],
        environment: Some(sky()),
        hash: 0,
        files: Vec::new(),
    }
}
