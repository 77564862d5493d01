//! The typical mistakes and correct alternatives of the exercises of the book's transport
//! chapters (see [`super`]).

use super::Table;

/// This part's tables, in the book's order.
pub const TABLES: &[Table] = &[];
