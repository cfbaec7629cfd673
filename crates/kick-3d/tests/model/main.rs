//! kick-3d's tests, one binary: the accurate path, the checks, the rapier scene.

mod accurate;
mod box_accuracy;
mod checks;
mod foot;
mod grip;
mod history;
mod line;
mod patch;
mod peaks;
mod scene;
mod support;
mod tangential;
mod validation;
