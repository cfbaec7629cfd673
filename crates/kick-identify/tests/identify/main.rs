//! kick-identify's tests, one binary: fits, laws, recovery of known truths, refusals.

mod common;
mod fit_refusals;
mod laws;
mod laws_and_offset;
mod measurements;
mod recovery;
mod table2;
mod validation;
