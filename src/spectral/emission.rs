//! Placeholder: filled by the emission section (issue 5).
