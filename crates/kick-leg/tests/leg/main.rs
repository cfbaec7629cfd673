//! kick-leg's tests, one binary: effective mass (Eq. 11) and the elastic ankle.

mod effective_mass;
mod elastic_ankle;
