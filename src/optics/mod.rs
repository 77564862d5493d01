//! Optics: reflection, refraction, Fresnel, specular deltas, dispersion and thin films.
//! Chapters: *Optics*.

pub mod dispersion;
pub mod fresnel;
pub mod reflect;
pub mod specular;
pub mod thinfilm;
