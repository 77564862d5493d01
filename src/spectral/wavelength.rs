//! Placeholder: filled by the wavelength section (issue 5).
