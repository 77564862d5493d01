//! The tools for implementers of other renderers, beside the renderer (`crate::render`),
//! which they read but which never reads them: a scene exported to Mitsuba 3, pbrt-v4 or
//! fully resolved JSON ([`export`]); the conformance ladder of scenes, one feature each
//! ([`ladder`]); independent renders pooled into one ([`merge`]); a candidate's EXR files
//! read ([`candidate`]) and compared with a reference within their noise ([`compare`]); a disagreement
//! diagnosed ([`diagnose`]); another renderer run on the whole ladder ([`run`]) and its
//! conformance card as text, JSON and JUnit ([`card`]). The images and their files (EXR header checks included) are
//! [`crate::image`]. Chapters: *Comparing images* (`chapters/renderer/compare.md`) and
//! *Reference scenes and interop* (`chapters/renderer/scenes.md`).

pub mod candidate;
pub mod card;
pub mod compare;
pub mod diagnose;
pub mod export;
pub mod ladder;
pub mod merge;
pub mod run;
