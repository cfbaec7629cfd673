//! Helpers shared by this crate's tests.
#![allow(dead_code)]

pub mod fine_rk4;
