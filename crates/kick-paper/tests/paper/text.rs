//! Text outputs print every value in one form (`kick_core::sig`: six
//! significant digits, plain between 1e-3 and 1e5, else `1.5e-12`), and
//! each printed value is the computed one rounded.

use kick_core::number::VALUE_DIGITS;
use kick_study::Printable;
use std::path::Path;

/// Every token with a decimal point or an exponent, as printed.
fn values(text: &str) -> Vec<String> {
    text.split(|c: char| c.is_whitespace() || "[],=():;".contains(c))
        .filter(|t| t.parse::<f64>().is_ok() && (t.contains('.') || t.contains('e')))
        .map(String::from)
        .collect()
}

/// One form: at most six significant digits, no trailing zeros, no `+`,
/// plain notation exactly for 1e-3 <= |x| < 1e5.
fn assert_one_form(text: &str) {
    let found = values(text);
    assert!(!found.is_empty(), "no values in {text}");
    for token in found {
        let x: f64 = token.parse().unwrap();
        let (mantissa, exponent) = token.split_once('e').unwrap_or((&token, ""));
        let digits = mantissa.chars().filter(char::is_ascii_digit).collect::<String>();
        let significant = digits.trim_start_matches('0').len();
        assert!(significant <= VALUE_DIGITS, "{token}: more than {VALUE_DIGITS} digits in\n{text}");
        assert!(!token.starts_with('+') && !exponent.starts_with('+') && !exponent.starts_with("0"), "{token}");
        assert!(!(mantissa.contains('.') && mantissa.ends_with('0')), "{token}: trailing zero");
        let plain = (1e-3..1e5).contains(&x.abs());
        assert_eq!(exponent.is_empty(), plain, "{token}: plain notation for 1e-3 <= |x| < 1e5 only");
    }
}

/// The value printed after `name` on its line, within rounding of `expected`.
fn assert_printed(text: &str, name: &str, expected: f64) {
    let line = text.lines().find(|l| l.split_whitespace().next() == Some(name)).unwrap_or_else(|| panic!("no {name} in\n{text}"));
    let printed: f64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    assert!((printed - expected).abs() <= 5e-6 * expected.abs(), "{name}: printed {printed}, computed {expected}");
}

#[test]
fn simulate_prints_values_in_the_one_form() {
    let run = kick_study::simulate::simulate(&Default::default(), "accurate", None, None, None).unwrap();
    let text = run.text();
    assert_one_form(&text);
    assert_printed(&text, "v_ball_out", run.outcome.v_ball_out);
    assert_printed(&text, "contact_time", run.outcome.contact_time);
    let kick = kick_3d::KickSpec { kick3d: kick_3d::Kick3dSpec { offset: Some(0.05), ..Default::default() }, ..Default::default() };
    let run = kick_study::simulate::simulate3d(&kick, "accurate", None, None, None).unwrap();
    assert_one_form(&run.text());
    assert_printed(&run.text(), "spin_rpm", run.outcome.spin_rpm);
}

#[test]
fn leg_laws_and_table2_print_values_in_the_one_form() {
    let leg = kick_study::leg::leg(&kick_study::leg::LegSettings::default()).unwrap();
    assert_one_form(&leg.text());
    assert_printed(&leg.text(), "effective_mass", leg.mass.effective_mass);
    let default = Path::new(kick_study::table2::DEFAULT_PATH);
    let laws =
        kick_paper::identify::laws(&kick_paper::identify::LawsSettings { scenarios: default.into(), out: None, samples: 20 }).unwrap();
    assert_one_form(&laws.text());
    // Table 2's paper column quotes the printed digits (`5.10`); the computed columns are ours.
    let table2 = kick_study::table2::compare(default).unwrap().text();
    let computed: Vec<String> = table2
        .lines()
        .map(|l| match l.strip_prefix("  ") {
            Some(row) => row.split_whitespace().enumerate().filter(|(i, _)| *i != 1).map(|(_, t)| t).collect::<Vec<_>>().join(" "),
            None => l.to_string(),
        })
        .collect();
    assert_one_form(&computed.join("\n"));
}

/// `kick fit data`: a table with the parameter, estimate, standard error
/// and unit; the stop reason in words.
#[test]
fn a_fit_prints_a_table_with_units() {
    let dir = crate::scratch("text");
    let written = kick_paper::identify::synthesize(&dir, "s", 3, 40, &Default::default(), 0.0, None).unwrap();
    let fit = kick_paper::identify::data(&written.spec, None).unwrap();
    let text = fit.text();
    assert_one_form(&text);
    let header = text.lines().nth(1).unwrap();
    let at: Vec<Option<usize>> = ["parameter", "estimate", "standard error", "unit"].iter().map(|c| header.find(c)).collect();
    assert!(at.iter().all(Option::is_some) && at.windows(2).all(|w| w[0] < w[1]), "columns in order: {header}");
    for e in &fit.report.estimates {
        let row = text.lines().find(|l| l.starts_with(e.parameter.name())).unwrap();
        assert!(row.contains(&format!(" {} ", e.parameter.unit())), "unit {} in {row}", e.parameter.unit());
        assert_printed(&text, e.parameter.name(), e.value);
    }
    assert!(text.contains("converged") && !text.contains("Converged") && !text.contains("ResidualsZero"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}
