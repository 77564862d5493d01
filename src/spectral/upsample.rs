//! Placeholder: filled by the upsample section (issue 5).
