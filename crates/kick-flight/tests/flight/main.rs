//! kick-flight's tests, one binary (the allocation count keeps its own, for its global allocator).

mod aim;
mod closed_forms;
mod robustness;
mod sources;
mod validation;
