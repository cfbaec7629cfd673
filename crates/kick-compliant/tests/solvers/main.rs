//! The 1D solvers' tests, one binary: each module holds the solvers to an
//! independent truth (closed forms, conservation laws, the paper's printed
//! numbers, each other over a stress box, refusals of bad input).

mod accurate_vs_closed_forms;
mod bad_input;
mod boot;
mod conservation;
mod contact_laws_everywhere;
mod history;
mod properties;
mod series;
mod shell_series;
mod step_size;
mod stress;
mod support;
mod table2;
