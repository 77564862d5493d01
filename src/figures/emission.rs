//! Figures of the chapter on emission (issue 5): filled by that section.

use super::Output;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    Vec::new()
}
