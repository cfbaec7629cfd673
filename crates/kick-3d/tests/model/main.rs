//! kick-3d's tests, one binary: the accurate path, the checks, the rapier scene.

mod accurate;
mod checks;
mod scene;
mod validation;
mod box_accuracy;
mod peaks;
mod grip;
mod history;
mod support;
mod patch;
