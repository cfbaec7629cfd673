//! Air: density for the forces, dynamic viscosity for the Reynolds number.
//!
//! Either the density is given (viscosity then at 15 °C), or it follows
//! from the ideal gas law ρ = p/(R_air T) with temperature, pressure and
//! altitude; what is left out comes from the International Standard
//! Atmosphere's troposphere (ISO 2533:1975; the same model as the U.S.
//! Standard Atmosphere 1976 below 11 km), altitude h taken as geopotential
//! (4 m below geometric at 5 km): T = T0 − L h,
//! p = p0 (1 − L h/T0)^(g0 M/(R* L)). Viscosity by Sutherland's law in the
//! standard atmosphere's form μ = β T^(3/2)/(T + S), β = 1.458e-6 kg/(m s K^½),
//! S = 110.4 K (same standards), 1.7894e-5 Pa s at sea level.

use crate::FlightError;
use serde::Serialize;

/// T0, K: standard sea-level temperature (15 °C).
pub const SEA_LEVEL_TEMPERATURE: f64 = 288.15;
/// p0, Pa.
pub const SEA_LEVEL_PRESSURE: f64 = 101_325.0;
/// L, K/m: the troposphere's temperature lapse rate.
pub const LAPSE_RATE: f64 = 0.0065;
/// R_air = R*/M for dry air, J/(kg K), with the standard atmosphere's own
/// R* = 8.31432 J/(mol K) and M = 0.0289644 kg/mol (so that p0/(R_air T0) is its 1.2250 kg/m³).
pub const GAS_CONSTANT_AIR: f64 = 8.31432 / 0.0289644;
/// g0 M/(R* L), the exponent of the troposphere's pressure law (g0 = 9.80665 m/s²).
pub const PRESSURE_EXPONENT: f64 = 9.80665 * 0.0289644 / (8.31432 * LAPSE_RATE);
/// Altitudes where the troposphere law above holds (−500 m … 11 km).
pub const ALTITUDE_RANGE: (f64, f64) = (-500.0, 11_000.0);
/// Default density: ρ of the standard atmosphere at sea level, kg/m³.
pub const SEA_LEVEL_DENSITY: f64 = 1.225;
/// 0 °C in K.
pub const CELSIUS_ZERO: f64 = 273.15;

/// β, kg/(m s K^½).
const SUTHERLAND_BETA: f64 = 1.458e-6;
/// S, K.
const SUTHERLAND_CONSTANT: f64 = 110.4;

/// Validated air properties.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Air {
    /// ρ, kg/m³.
    pub density: f64,
    /// μ, Pa s.
    pub viscosity: f64,
}

/// Sutherland's law, Pa s, at `kelvin`.
pub fn sutherland_viscosity(kelvin: f64) -> f64 {
    SUTHERLAND_BETA * kelvin * kelvin.sqrt() / (kelvin + SUTHERLAND_CONSTANT)
}

/// The hottest air accepted, °C: a bound of the numbers, far above any
/// pitch's air; without one the viscosity (T^1.5) ran to inf and the drag
/// to NaN (1e300 °C).
pub const MAX_TEMPERATURE: f64 = 1000.0;
pub(crate) const TEMPERATURE_REQUIREMENT: &str = "finite, above absolute zero (-273.15 °C) and at most 1000 °C";

/// Standard-atmosphere temperature (K) and pressure (Pa) at `altitude` (m).
pub fn standard_atmosphere(altitude: f64) -> (f64, f64) {
    let ratio = 1.0 - LAPSE_RATE * altitude / SEA_LEVEL_TEMPERATURE;
    (SEA_LEVEL_TEMPERATURE * ratio, SEA_LEVEL_PRESSURE * ratio.powf(PRESSURE_EXPONENT))
}

fn invalid(name: &'static str, value: f64, requirement: &'static str) -> FlightError {
    FlightError::InvalidParameter { name, value, requirement }
}

impl Air {
    /// The standard atmosphere at sea level.
    pub fn standard() -> Air {
        Air { density: SEA_LEVEL_DENSITY, viscosity: sutherland_viscosity(SEA_LEVEL_TEMPERATURE) }
    }

    /// From what the user gave: `density` (kg/m³) alone, or any of
    /// `temperature` (°C), `pressure` (Pa), `altitude` (m).
    pub fn new(density: Option<f64>, temperature: Option<f64>, pressure: Option<f64>, altitude: Option<f64>) -> Result<Air, FlightError> {
        if let Some(rho) = density {
            for (name, given) in [("temperature", temperature), ("pressure", pressure), ("altitude", altitude)] {
                if given.is_some() {
                    return Err(FlightError::Conflict { first: "air_density", second: name });
                }
            }
            if !(rho.is_finite() && rho > 0.0) {
                return Err(invalid("air_density", rho, "finite and > 0, kg/m^3"));
            }
            return Ok(Air { density: rho, viscosity: sutherland_viscosity(SEA_LEVEL_TEMPERATURE) });
        }
        if temperature.is_none() && pressure.is_none() && altitude.is_none() {
            return Ok(Air::standard());
        }
        if let (Some(_), Some(_), Some(_)) = (temperature, pressure, altitude) {
            // Altitude only supplies what is not given: with both, it would be ignored.
            return Err(FlightError::Conflict { first: "altitude", second: "temperature and pressure" });
        }
        let h = altitude.unwrap_or(0.0);
        if !(h.is_finite() && h >= ALTITUDE_RANGE.0 && h <= ALTITUDE_RANGE.1) {
            return Err(invalid("altitude", h, "finite, in [-500, 11000] m (the standard atmosphere's troposphere)"));
        }
        let (t_standard, p_standard) = standard_atmosphere(h);
        let kelvin = match temperature {
            Some(c) if c.is_finite() && c > -CELSIUS_ZERO && c <= MAX_TEMPERATURE => c + CELSIUS_ZERO,
            Some(c) => return Err(invalid("temperature", c, TEMPERATURE_REQUIREMENT)),
            None => t_standard,
        };
        let pressure = match pressure {
            Some(p) if p.is_finite() && p > 0.0 => p,
            Some(p) => return Err(invalid("pressure", p, "finite and > 0, Pa")),
            None => p_standard,
        };
        Ok(Air { density: pressure / (GAS_CONSTANT_AIR * kelvin), viscosity: sutherland_viscosity(kelvin) })
    }

    /// ν = μ/ρ, m²/s.
    pub fn kinematic_viscosity(&self) -> f64 {
        self.viscosity / self.density
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn standard_sea_level() {
        // ISA sea level: 1.2250 kg/m³, 1.7894e-5 Pa s (ISO 2533 tables).
        assert_eq!(Air::new(None, None, None, None).unwrap(), Air::standard());
        let air = Air::new(None, None, None, Some(0.0)).unwrap();
        assert!((air.density - 1.2250).abs() < 5e-5, "{}", air.density);
        assert!((air.viscosity - 1.7894e-5).abs() < 5e-10, "{}", air.viscosity);
    }

    #[test]
    fn standard_altitudes() {
        // ISA tables by geopotential altitude (ICAO Doc 7488): 1000 m: 89875 Pa,
        // 1.1116 kg/m³; 2000 m: 79495 Pa, 1.0065 kg/m³; 5000 m: 54020 Pa, 0.73612 kg/m³.
        for (h, p, rho) in [(1000.0, 89875.0, 1.1116), (2000.0, 79495.0, 1.0065), (5000.0, 54020.0, 0.73612)] {
            let (_, pressure) = standard_atmosphere(h);
            assert!((pressure - p).abs() < 1.0, "{h}: {pressure}");
            let air = Air::new(None, None, None, Some(h)).unwrap();
            assert!((air.density - rho).abs() < 2e-4 * rho, "{h}: {}", air.density);
        }
    }

    #[test]
    fn refusals_name_the_key() {
        let name = |r: Result<Air, FlightError>| match r {
            Err(FlightError::InvalidParameter { name, .. }) => name,
            Err(FlightError::Conflict { first, .. }) => first,
            other => panic!("{other:?}"),
        };
        assert_eq!(name(Air::new(Some(0.0), None, None, None)), "air_density");
        assert_eq!(name(Air::new(Some(f64::NAN), None, None, None)), "air_density");
        assert_eq!(name(Air::new(Some(1.2), Some(20.0), None, None)), "air_density");
        assert_eq!(name(Air::new(None, Some(-300.0), None, None)), "temperature");
        assert_eq!(name(Air::new(None, Some(1e300), None, None)), "temperature");
        assert!(Air::new(None, Some(1000.0), None, None).is_ok());
        assert_eq!(name(Air::new(None, None, Some(-1.0), None)), "pressure");
        assert_eq!(name(Air::new(None, None, None, Some(50_000.0))), "altitude");
        assert_eq!(name(Air::new(None, Some(20.0), Some(1e5), Some(10.0))), "altitude");
    }
}
