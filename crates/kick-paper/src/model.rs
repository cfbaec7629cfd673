//! `paper/model.md`: the model kick implements, stated in the project's own
//! words with the equations numbered as the paper (*The Millisecond Physics of
//! a Soccer Kick*) numbers them, so that a `// Eq. 20` in the code can be
//! looked up in a clone, and kick's own models beside it with letter labels.
//!
//! The text lives in Markdown parts under `src/model/`, one file per model,
//! so that whoever changes a model updates one file ([`PARTS`]). Placeholders
//! in the parts are filled from the code's declarations when the page is
//! made ([`render`]):
//!
//! - `{{eq 20}}`, `{{eq S1}}`: defines an equation label (an anchor `eq-20`,
//!   `eq-s1` and the bold label); each label is defined once;
//! - `{{p NAME}}`: one line for a declared parameter — symbol, meaning, unit,
//!   name and numeric default — from `kick_core::parameters::PARAMETERS`;
//!   `flight.NAME` from `kick_flight::FLIGHT_PARAMETERS`, `bounce.NAME` from
//!   `kick_bounce::BOUNCE_PARAMETERS`;
//! - `{{symbol NAME}}`, `{{unit NAME}}`, `{{default NAME}}`: one field of it;
//! - `{{parameters}}`: the index of every declared parameter with the labels
//!   of the equations whose symbol lists name it.
//!
//! `kick reproduce` writes the page ([`write`], step `model`); the tests
//! below keep the committed page current, make every equation number the
//! workspace cites a label of the page, and every code path it names exist.

use kick_study::parameters::{DefaultValue, ParameterDef, Shape, BOUNCE_PARAMETERS, FLIGHT_PARAMETERS, PARAMETERS};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The page's file name, beside the report.
pub const PAGE: &str = "model.md";

/// Where the parts live, for messages and the page's own pointers.
pub const PARTS_DIR: &str = "crates/kick-paper/src/model";

/// The paper's equations run from 1 to this.
pub const PAPER_EQUATIONS: u32 = 61;

/// The parts of the page in order: (file in [`PARTS_DIR`], its text).
pub const PARTS: [(&str, &str); 11] = [
    ("intro.md", include_str!("model/intro.md")),
    ("paper.md", include_str!("model/paper.md")),
    ("solvers-1d.md", include_str!("model/solvers-1d.md")),
    ("laws.md", include_str!("model/laws.md")),
    ("shell-ball.md", include_str!("model/shell-ball.md")),
    ("kick3d.md", include_str!("model/kick3d.md")),
    ("kick3d-tangential.md", include_str!("model/kick3d-tangential.md")),
    ("instep-patch.md", include_str!("model/instep-patch.md")),
    ("flight.md", include_str!("model/flight.md")),
    ("leg.md", include_str!("model/leg.md")),
    ("symbols.md", include_str!("model/symbols.md")),
];

/// Why the page could not be made or written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelPageError {
    #[error("{PARTS_DIR}/{part}:{line}: `{{{{` is never closed")]
    Unclosed { part: String, line: usize },
    #[error("{PARTS_DIR}/{part}:{line}: unknown placeholder `{{{{{text}}}}}` (eq, p, symbol, unit, default, parameters)")]
    UnknownPlaceholder { part: String, line: usize, text: String },
    #[error(
        "{PARTS_DIR}/{part}:{line}: `{name}` is not a declared parameter (kick_core::parameters::PARAMETERS; \
         `flight.NAME` for kick_flight::FLIGHT_PARAMETERS, `bounce.NAME` for kick_bounce::BOUNCE_PARAMETERS)"
    )]
    UnknownParameter { part: String, line: usize, name: String },
    #[error("{PARTS_DIR}/{part}:{line}: `{label}` is no equation label (1 to {PAPER_EQUATIONS} for the paper's, letters and a number for kick's own, e.g. S1)")]
    BadLabel { part: String, line: usize, label: String },
    #[error("{PARTS_DIR}/{part}:{line}: equation {label} is defined a second time")]
    DuplicateLabel { part: String, line: usize, label: String },
    #[error("cannot write {path}: {reason}")]
    Write { path: PathBuf, reason: String },
}

/// The made page.
#[derive(Debug, Clone, PartialEq)]
pub struct Page {
    pub text: String,
    /// Equation labels in page order, as written (`20`, `S1`).
    pub labels: Vec<String>,
    /// For each declared parameter (`name`, `flight.name`, `bounce.name`) the
    /// labels whose symbol lists name it.
    pub used: BTreeMap<String, Vec<String>>,
}

impl Page {
    /// The paper's equation numbers the page defines.
    pub fn paper_equations(&self) -> BTreeSet<u32> {
        self.labels.iter().filter_map(|l| l.parse().ok()).collect()
    }
}

/// Which declared list a name is in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum List {
    Kick,
    Flight,
    Bounce,
}

impl List {
    fn split(name: &str) -> (List, &str) {
        match name.split_once('.') {
            Some(("flight", rest)) => (List::Flight, rest),
            Some(("bounce", rest)) => (List::Bounce, rest),
            _ => (List::Kick, name),
        }
    }
    fn all(self) -> &'static [ParameterDef] {
        match self {
            List::Kick => &PARAMETERS,
            List::Flight => &FLIGHT_PARAMETERS,
            List::Bounce => &BOUNCE_PARAMETERS,
        }
    }
    fn prefix(self) -> &'static str {
        match self {
            List::Kick => "",
            List::Flight => "flight.",
            List::Bounce => "bounce.",
        }
    }
}

fn lookup(name: &str) -> Option<&'static ParameterDef> {
    let (list, rest) = List::split(name);
    list.all().iter().find(|p| p.name == rest)
}

/// The bounce's own parameters: those that are not the kick's declarations.
fn bounce_own() -> impl Iterator<Item = &'static ParameterDef> {
    BOUNCE_PARAMETERS.iter().filter(|b| !PARAMETERS.iter().any(|k| k == *b))
}

/// Every declared parameter the page must name, as `{{p}}` takes it.
pub fn declared_names() -> Vec<String> {
    let kick = PARAMETERS.iter().map(|p| p.name.to_string());
    let flight = FLIGHT_PARAMETERS.iter().map(|p| format!("flight.{}", p.name));
    let bounce = bounce_own().map(|p| format!("bounce.{}", p.name));
    kick.chain(flight).chain(bounce).collect()
}

fn unit(p: &ParameterDef) -> &'static str {
    match p.unit {
        "1" => "dimensionless",
        "" => "a switch",
        u => u,
    }
}

/// The doc line without a trailing equation reference (the page gives it).
fn meaning(p: &ParameterDef) -> &'static str {
    let doc = p.doc.trim_end();
    match doc.rfind(" (Eq") {
        Some(i) if doc.ends_with(')') => &doc[..i],
        _ => doc,
    }
}

/// A default short enough for a symbol line: numbers, vectors, off.
fn short_default(p: &ParameterDef) -> Option<String> {
    match p.default {
        DefaultValue::Number(_) | DefaultValue::Vector(_) | DefaultValue::Off => Some(p.default.text()),
        DefaultValue::Derived(_) | DefaultValue::Unset(_) => None,
    }
}

fn symbol_line(name: &str, p: &ParameterDef) -> String {
    let shape = if p.shape == Shape::Vector3 { " (three components)" } else { "" };
    let default = short_default(p).map(|d| format!(", default {d}")).unwrap_or_default();
    format!("{}: {}{shape}, {} (`{name}`{default})", p.symbol, meaning(p), unit(p))
}

/// `20` → `eq-20`, `S1` → `eq-s1`.
pub fn anchor(label: &str) -> String {
    format!("eq-{}", label.to_lowercase())
}

/// `20` → `Eq. 20`, `S1` → `(S1)`.
pub fn label_text(label: &str) -> String {
    if label.bytes().all(|b| b.is_ascii_digit()) {
        format!("Eq. {label}")
    } else {
        format!("({label})")
    }
}

fn valid_label(label: &str) -> bool {
    if let Ok(n) = label.parse::<u32>() {
        return (1..=PAPER_EQUATIONS).contains(&n) && !label.starts_with('0');
    }
    let letters = label.bytes().take_while(|b| b.is_ascii_uppercase()).count();
    letters > 0 && letters < label.len() && label[letters..].bytes().all(|b| b.is_ascii_digit()) && !label[letters..].starts_with('0')
}

const INDEX: &str = "\u{0}parameters\u{0}";

/// The page from `parts` (the real page: [`page`]).
pub fn render(parts: &[(&str, &str)]) -> Result<Page, ModelPageError> {
    let mut text = String::from(
        "<!-- Generated by `kick reproduce` (step `model`: `kick reproduce --only model`) from the parts in \
         crates/kick-paper/src/model/ and the declared parameters; do not edit this file: edit the part named \
         above each section (tests in crates/kick-paper/src/model.rs keep it current). -->\n\n",
    );
    let mut labels: Vec<String> = Vec::new();
    let mut used: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for (part, source) in parts {
        let _ = writeln!(text, "<!-- part: {PARTS_DIR}/{part} -->\n");
        let mut current: Option<String> = None;
        let mut rest = *source;
        let line_of = |rest: &str| source[..source.len() - rest.len()].matches('\n').count() + 1;
        while let Some(start) = rest.find("{{") {
            text.push_str(&rest[..start]);
            let line = line_of(&rest[start..]);
            let Some(end) = rest[start..].find("}}") else {
                return Err(ModelPageError::Unclosed { part: part.to_string(), line });
            };
            let inner = rest[start + 2..start + end].trim();
            rest = &rest[start + end + 2..];
            let (kind, argument) = inner.split_once(' ').map(|(k, a)| (k, a.trim())).unwrap_or((inner, ""));
            let parameter = |name: &str| {
                lookup(name).ok_or_else(|| ModelPageError::UnknownParameter { part: part.to_string(), line, name: name.to_string() })
            };
            match kind {
                "eq" => {
                    if !valid_label(argument) {
                        return Err(ModelPageError::BadLabel { part: part.to_string(), line, label: argument.to_string() });
                    }
                    if labels.iter().any(|l| l == argument) {
                        return Err(ModelPageError::DuplicateLabel { part: part.to_string(), line, label: argument.to_string() });
                    }
                    labels.push(argument.to_string());
                    current = Some(argument.to_string());
                    let _ = write!(text, "<a id=\"{}\"></a>**{}**", anchor(argument), label_text(argument));
                }
                "p" | "symbol" | "unit" | "default" if !argument.is_empty() => {
                    let p = parameter(argument)?;
                    let (list, _) = List::split(argument);
                    let key = format!("{}{}", list.prefix(), p.name);
                    let entry = used.entry(key).or_default();
                    if let Some(label) = &current {
                        if kind == "p" && !entry.contains(label) {
                            entry.push(label.clone());
                        }
                    }
                    text.push_str(&match kind {
                        "p" => symbol_line(p.name, p),
                        "symbol" => p.symbol.to_string(),
                        "unit" => unit(p).to_string(),
                        _ => p.default.text(),
                    });
                }
                "parameters" if argument.is_empty() => text.push_str(INDEX),
                _ => return Err(ModelPageError::UnknownPlaceholder { part: part.to_string(), line, text: inner.to_string() }),
            }
        }
        text.push_str(rest);
        if !text.ends_with("\n\n") {
            text.push('\n');
        }
    }
    let index = parameter_index(&used);
    let text = text.replace(INDEX, &index).trim_end().to_string() + "\n";
    Ok(Page { text, labels, used })
}

/// One Markdown table cell.
fn cell(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ").replace('|', "\\|")
}

/// The index: each declared list, each parameter with its symbol, unit,
/// meaning, default and the equations that name it.
fn parameter_index(used: &BTreeMap<String, Vec<String>>) -> String {
    let mut out = String::new();
    let lists: [(&str, List, Vec<&'static ParameterDef>); 3] = [
        ("The kick (`kick_core::parameters::PARAMETERS`)", List::Kick, List::Kick.all().iter().collect()),
        ("The flight (`kick_flight::FLIGHT_PARAMETERS`; written `flight.NAME` above)", List::Flight, List::Flight.all().iter().collect()),
        (
            "The bounce's own (`kick_bounce::BOUNCE_PARAMETERS` beyond the kick's; written `bounce.NAME` above)",
            List::Bounce,
            bounce_own().collect(),
        ),
    ];
    for (title, list, parameters) in lists {
        let _ = writeln!(out, "**{title}**\n");
        out.push_str("| name | symbol | unit | meaning | default | in |\n| --- | --- | --- | --- | --- | --- |\n");
        for p in parameters {
            let key = format!("{}{}", list.prefix(), p.name);
            let labels =
                used.get(&key).map(|ls| ls.iter().map(|l| format!("[{}](#{})", label_text(l), anchor(l))).collect::<Vec<_>>().join(", "));
            let _ = writeln!(
                out,
                "| `{}` | {} | {} | {} | {} | {} |",
                p.name,
                cell(p.symbol),
                cell(unit(p)),
                cell(meaning(p)),
                cell(&p.default.text()),
                labels.unwrap_or_default()
            );
        }
        out.push('\n');
    }
    out.trim_end().to_string()
}

/// The page from [`PARTS`].
pub fn page() -> Result<Page, ModelPageError> {
    render(&PARTS)
}

/// Write the page to `path` (whole or not at all).
pub fn write(path: &Path) -> Result<PathBuf, ModelPageError> {
    let page = page()?;
    crate::output::write(path, page.text).map_err(|e| ModelPageError::Write { path: path.to_path_buf(), reason: e.to_string() })
}

/// The paper's equation numbers `text` cites: `Eq. 20`, `Eq. (20)`,
/// `Eqs. 13–20` (en dash or hyphen), `Eqs. 13–14, 20`, `Eqs. 18 and 23`.
/// A singular `Eq.` takes one number or one range (`Eq. 11–12`), so the
/// numbers after `Eq. 4, ` are not read as a list.
pub fn cited_equations(text: &str) -> BTreeSet<u32> {
    let mut cited = BTreeSet::new();
    let bytes = text.as_bytes();
    let mut from = 0;
    while let Some(found) = text[from..].find("Eq") {
        let at = from + found;
        from = at + 2;
        if at > 0 && (bytes[at - 1].is_ascii_alphanumeric() || bytes[at - 1] == b'_') {
            continue;
        }
        let rest = &text[at + 2..];
        let (plural, rest) = match rest.strip_prefix("s.") {
            Some(r) => (true, r),
            None => match rest.strip_prefix('.') {
                Some(r) => (false, r),
                None => continue,
            },
        };
        let mut rest = rest.trim_start_matches([' ', '\u{a0}']);
        loop {
            let Some((numbers, after)) = number_or_range(rest) else { break };
            cited.extend(numbers);
            rest = after;
            if !plural {
                break;
            }
            let next = [", and ", ", ", " and "].iter().find_map(|sep| rest.strip_prefix(sep));
            match next {
                Some(r) if number_or_range(r).is_some() => rest = r,
                _ => break,
            }
        }
    }
    cited
}

/// A number `N` or range `N–M` / `N-M` at the start of `s`, optionally in
/// parentheses (`(13)–(14)`), not a decimal; what follows it.
fn number_or_range(s: &str) -> Option<(Vec<u32>, &str)> {
    let (first, rest) = integer(s)?;
    for dash in ["–", "-"] {
        if let Some((last, after)) = rest.strip_prefix(dash).and_then(integer) {
            if last > first && last - first < 100 {
                return Some(((first..=last).collect(), after));
            }
        }
    }
    Some((vec![first], rest))
}

fn integer(s: &str) -> Option<(u32, &str)> {
    let (open, s) = match s.strip_prefix('(') {
        Some(r) => (true, r),
        None => (false, s),
    };
    let digits = s.bytes().take_while(u8::is_ascii_digit).count();
    if digits == 0 || digits > 4 {
        return None;
    }
    let rest = &s[digits..];
    // A decimal (`Eq. 4, 0.41`) or a longer word is not an equation number.
    if rest.starts_with('.') && rest[1..].starts_with(|c: char| c.is_ascii_digit()) {
        return None;
    }
    if rest.starts_with(|c: char| c.is_alphanumeric()) {
        return None;
    }
    let rest = if open { rest.strip_prefix(')')? } else { rest };
    Some((s[..digits].parse().ok()?, rest))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn root() -> PathBuf {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        root.canonicalize().unwrap_or(root)
    }

    /// The committed `paper/model.md` is what the parts and declarations make now.
    #[test]
    fn the_committed_page_is_current() {
        let made = page().expect("the page is made").text;
        let path = root().join("paper").join(PAGE);
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            committed == made,
            "paper/{PAGE} is stale (or missing): rewrite it with `cargo run --release --bin kick -- reproduce --only model` \
             and commit it"
        );
        assert_eq!(page().unwrap().text, made, "not the same bytes twice");
    }

    /// Every file of the workspace a reader may meet a citation in.
    fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else { return };
        let mut entries: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        entries.sort();
        for path in entries {
            let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
            if name.starts_with('.') || name == "target" {
                continue;
            }
            if path.is_dir() {
                sources(&path, out);
            } else if ["rs", "md", "toml", "py", "pyi"].iter().any(|x| path.extension().is_some_and(|e| e == *x)) {
                out.push(path);
            }
        }
    }

    /// Every `Eq. N` / `Eqs. N–M` in the workspace's sources (crates, tests,
    /// experiments, the README; not the generated results/ and paper/) is
    /// defined on the page. (kick-flight's `Eq. 3` and `Eq. 4` are Goff &
    /// Carré's; the page defines the paper's 3 and 4 and says so there.)
    #[test]
    fn every_equation_the_code_cites_is_on_the_page() {
        let defined = page().unwrap().paper_equations();
        let mut files = vec![root().join("README.md")];
        for dir in ["crates", "tests", "experiments"] {
            sources(&root().join(dir), &mut files);
        }
        assert!(files.len() > 200, "found only {} source files", files.len());
        let mut missing: BTreeMap<u32, Vec<String>> = BTreeMap::new();
        let mut cited_anywhere = BTreeSet::new();
        for file in &files {
            let text = std::fs::read_to_string(file).unwrap_or_default();
            for (i, line) in text.lines().enumerate() {
                for n in cited_equations(line) {
                    cited_anywhere.insert(n);
                    if !defined.contains(&n) {
                        missing.entry(n).or_default().push(format!("{}:{}", file.display(), i + 1));
                    }
                }
            }
        }
        assert!(missing.is_empty(), "cited but not on paper/{PAGE}: {missing:#?}");
        // The scan reads what it should: Eq. 20 and a range's inside (Eqs. 13–20 gives 15).
        assert!(cited_anywhere.contains(&20) && cited_anywhere.contains(&15) && cited_anywhere.contains(&61), "{cited_anywhere:?}");
    }

    /// The scan reads every way the workspace writes a citation, and no
    /// more; a number the page lacks is reported.
    #[test]
    fn citations_are_read_in_every_written_form() {
        let read = |s: &str| cited_equations(s).into_iter().collect::<Vec<_>>();
        assert_eq!(read("// Eq. 20"), [20]);
        assert_eq!(read("(Eq. (6))"), [6]);
        assert_eq!(read("Eqs. 13–20 and more"), (13..=20).collect::<Vec<_>>());
        assert_eq!(read("\"Eqs. 1-2\""), [1, 2]);
        assert_eq!(read("(Eqs. 13–14, 20)"), [13, 14, 20]);
        assert_eq!(read("(Eqs. 18, 23)."), [18, 23]);
        assert_eq!(read("Eqs. 30 and 33"), [30, 33]);
        assert_eq!(read("Eq. 11–12 and Eq. 37's e"), [11, 12, 37]);
        assert_eq!(read("close to Eq. 4, 0.4127 * 0.2**0.3056"), [4]);
        assert_eq!(read("Eq. 3.5 is no number; FreqEq. 9 is no citation; Eqn 7 neither"), Vec::<u32>::new());
        assert_eq!(read("Eq. 20's max(δ̇, 0); Eq. 48)"), [20, 48]);
        let defined = page().unwrap().paper_equations();
        // Written so that this file does not cite it itself.
        let beyond = format!("// Eq. {}: a number past the paper's", PAPER_EQUATIONS + 1);
        let missing: Vec<u32> = cited_equations(&beyond).difference(&defined).copied().collect();
        assert_eq!(missing, [PAPER_EQUATIONS + 1]);
    }

    /// Each of the paper's equations has its label, once, in the paper's order.
    #[test]
    fn the_page_defines_every_equation_of_the_paper_once_in_order() {
        let page = page().unwrap();
        let numbers: Vec<u32> = page.labels.iter().filter_map(|l| l.parse().ok()).collect();
        assert_eq!(numbers, (1..=PAPER_EQUATIONS).collect::<Vec<_>>());
        for n in 1..=PAPER_EQUATIONS {
            assert_eq!(page.text.matches(&format!("<a id=\"eq-{n}\"></a>**Eq. {n}**")).count(), 1, "Eq. {n}");
        }
        // kick's own labels: letters and a number, each once (render refuses a second).
        assert!(page.labels.iter().filter(|l| l.parse::<u32>().is_err()).count() >= 30, "{:?}", page.labels);
        assert!(page.text.contains("*The Millisecond Physics of a Soccer Kick*"), "the paper is cited by title");
        assert!(!page.text.contains("{{") && !page.text.contains('\u{0}'), "a placeholder is left");
    }

    /// The page names every declared parameter of the kick, the flight and
    /// the bounce in an equation's symbol list, with its declared symbol and unit.
    #[test]
    fn every_declared_parameter_is_on_the_page() {
        let page = page().unwrap();
        let unnamed: Vec<String> = declared_names().into_iter().filter(|n| page.used.get(n).is_none_or(|ls| ls.is_empty())).collect();
        assert!(unnamed.is_empty(), "declared but in no symbol list ({{{{p NAME}}}} under an equation): {unnamed:?}");
        let stiffness = kick_study::parameters::find("stiffness").unwrap();
        assert!(page.text.contains(&format!("{}: Contact stiffness, {} (`stiffness`, default 4.2e5)", stiffness.symbol, stiffness.unit)));
    }

    /// Every link on the page lands: `#name` on an `<a id="name">` of the
    /// page, a relative path on a file beside `paper/model.md`.
    #[test]
    fn every_link_on_the_page_lands() {
        let text = page().unwrap().text;
        let after = |i: usize, end: char| text[i..].split(end).next().unwrap_or("");
        let ids: BTreeSet<&str> = text.match_indices("<a id=\"").map(|(i, m)| after(i + m.len(), '"')).collect();
        let mut broken = Vec::new();
        let mut links = 0;
        for (i, m) in text.match_indices("](") {
            let target = after(i + m.len(), ')');
            links += 1;
            match target.strip_prefix('#') {
                Some(id) if !ids.contains(id) => broken.push(target),
                Some(_) => {}
                None if !root().join("paper").join(target.split('#').next().unwrap_or("")).exists() => broken.push(target),
                None => {}
            }
        }
        assert!(broken.is_empty(), "links that land nowhere: {broken:?}");
        assert!(links >= 80, "only {links} links");
    }

    /// Source text of a crate (its src/ tree).
    fn crate_text(dir: &Path, text: &mut String, files: &mut Vec<String>) {
        let Ok(entries) = std::fs::read_dir(dir) else { return };
        for entry in entries.filter_map(|e| e.ok()) {
            let path = entry.path();
            if path.is_dir() {
                files.push(path.file_name().unwrap().to_string_lossy().into_owned());
                crate_text(&path, text, files);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path.file_stem().unwrap().to_string_lossy().into_owned());
                text.push_str(&std::fs::read_to_string(&path).unwrap_or_default());
                text.push('\n');
            }
        }
    }

    /// `keyword name` in `text`, `name` not followed by more of an identifier.
    fn declares(text: &str, keyword: &str, name: &str) -> bool {
        let needle = format!("{keyword} {name}");
        text.match_indices(&needle).any(|(i, _)| !text[i + needle.len()..].starts_with(|c: char| c.is_alphanumeric() || c == '_'))
    }

    /// Every code path the page names (`kick_core::PowerLawContact::force`)
    /// names items its crate declares: modules, functions, types, constants
    /// or enum variants. A rename that leaves the page behind fails here.
    #[test]
    fn every_code_path_on_the_page_exists() {
        let page = page().unwrap();
        let mut checked = 0;
        let mut stale = Vec::new();
        let mut crates: BTreeMap<String, (String, Vec<String>)> = BTreeMap::new();
        for span in page.text.split('`').skip(1).step_by(2) {
            let path = span.trim_end_matches("()");
            let segments: Vec<&str> = path.split("::").collect();
            let is_path = segments.len() > 1
                && segments[0].starts_with("kick_")
                && segments.iter().all(|s| !s.is_empty() && s.chars().all(|c| c.is_alphanumeric() || c == '_'));
            if !is_path {
                continue;
            }
            let dir = root().join("crates").join(segments[0].replace('_', "-"));
            let (text, files) = crates.entry(segments[0].to_string()).or_insert_with(|| {
                let (mut text, mut files) = (String::new(), Vec::new());
                crate_text(&dir.join("src"), &mut text, &mut files);
                (text, files)
            });
            assert!(!text.is_empty(), "`{span}`: no crate at {}", dir.display());
            for s in &segments[1..] {
                let item = ["fn", "struct", "enum", "trait", "const", "static", "type", "mod"].iter().any(|k| declares(text, k, s));
                let variant = text.lines().any(|l| {
                    l.trim_start().strip_prefix(s).is_some_and(|r| r.starts_with([',', ' ', '(', '{']) || r.is_empty())
                        && s.starts_with(|c: char| c.is_uppercase())
                });
                if !(item || variant || files.iter().any(|f| f == s)) {
                    stale.push(format!("`{span}`: no `{s}` in {}", dir.display()));
                }
            }
            checked += 1;
        }
        assert!(stale.is_empty(), "{stale:#?}");
        assert!(checked >= 60, "only {checked} code paths on the page");
    }

    /// A placeholder the page cannot fill is refused with the part, the
    /// line and the name, never written as it stands.
    #[test]
    fn bad_placeholders_are_refused_by_name() {
        let error = |text: &str| render(&[("x.md", text)]).unwrap_err().to_string();
        assert_eq!(
            error("a\n{{p no_such}}"),
            "crates/kick-paper/src/model/x.md:2: `no_such` is not a declared parameter (kick_core::parameters::PARAMETERS; \
             `flight.NAME` for kick_flight::FLIGHT_PARAMETERS, `bounce.NAME` for kick_bounce::BOUNCE_PARAMETERS)"
        );
        assert!(error("{{eq 20}} {{eq 20}}").ends_with("x.md:1: equation 20 is defined a second time"));
        assert!(error("{{eq 62}}").contains("`62` is no equation label"));
        assert!(error("{{eq s1}}").contains("`s1` is no equation label"));
        assert!(error("{{pp stiffness}}").contains("unknown placeholder `{{pp stiffness}}`"));
        assert!(error("{{p stiffness").contains("`{{` is never closed"));
        let made = render(&[("x.md", "{{eq S2}} with {{p flight.spin}}; {{symbol bounce.angle}} in {{unit bounce.angle}}")]).unwrap();
        assert!(made.text.contains("<a id=\"eq-s2\"></a>**(S2)** with ω: Spin vector at launch"), "{}", made.text);
        assert!(made.text.contains("(three components), rad/s (`spin`, default 0,0,0); θ in deg"), "{}", made.text);
        assert_eq!(made.used["flight.spin"], ["S2"]);
    }
}
