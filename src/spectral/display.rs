//! Placeholder: filled by the display section (issue 5).
