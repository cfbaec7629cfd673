//! The aimed free kicks of paper/flight.md (`kick aim`): the two requests
//! the page solves and `kick bench` times, past the free kick's wall to a
//! target under the bar by the post.

use crate::free_kick::GOAL_DISTANCE;

/// The aimed free kick of paper/flight.md: the ball's centre 2.6 m to the
/// +y side of the goal's centre and 2 m up at the goal line (under the bar
/// by the post), past the default wall.
pub const AIM_TARGET: [f64; 3] = [GOAL_DISTANCE, 2.6, 2.0];
/// Its launch aim holds this sidespin (about 8 rev/s, curving toward +y).
pub const AIM_SPIN: [f64; 3] = [0.0, 0.0, 50.0];

/// The two aims of the page: the launch (speed, elevation, azimuth free,
/// [`AIM_SPIN`] held) and the 3D kick (foot speed, e, h, heading free, the
/// member of their family with the most room at the wall), to
/// [`AIM_TARGET`]; `kick bench` times the same two.
pub fn aim_requests() -> [crate::aim::AimRequest; 2] {
    use crate::aim::{AimFrom, AimRequest};
    let launch = AimRequest {
        target: Some(AIM_TARGET),
        from: Some(AimFrom::Launch),
        flight: kick_flight::FlightSpec { spin: Some(AIM_SPIN), ..kick_flight::FlightSpec::default() },
        ..AimRequest::default()
    };
    let kick = AimRequest {
        target: Some(AIM_TARGET),
        from: Some(AimFrom::Kick),
        objective: Some(kick_flight::Objective::MaxClearance),
        ..AimRequest::default()
    };
    [launch, kick]
}

/// The page's two aims ([`aim_requests`]) solved.
pub fn aims() -> Result<[crate::aim::AimReport; 2], crate::error::StudyError> {
    let [launch, kick] = aim_requests();
    Ok([crate::aim::aim(&launch)?, crate::aim::aim(&kick)?])
}
