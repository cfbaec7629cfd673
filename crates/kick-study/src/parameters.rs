//! Every declared parameter a study can set, hold or sweep, in one place:
//! the kick's (1D and 3D levels and the foot), the flight's and the ball
//! alone's. Pages and reference tables read the declarations from here.

pub use kick_bounce::BOUNCE_PARAMETERS;
pub use kick_core::parameters::*;
// The scenario's declared names, as pages and command lines spell them.
pub use kick_core::{LawKind, Parameter, Scenario, ScenarioSpec, DEFAULT_BALL_RADIUS};
pub use kick_flight::FLIGHT_PARAMETERS;
