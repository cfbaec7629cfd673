//! Links between generated pages and files.

use std::path::{Component, Path, PathBuf};

/// `to` relative to the directory `from`, both relative to the working
/// directory or both absolute: e.g. paper → results/figures gives
/// ../results/figures, and so does /tmp/x/paper → /tmp/x/results/figures
/// (a check in a temporary folder writes the same links).
pub fn relative(from: &Path, to: &Path) -> String {
    if from.is_absolute() != to.is_absolute() {
        return to.display().to_string();
    }
    let from: Vec<Component> = from.components().filter(|c| !matches!(c, Component::CurDir)).collect();
    let to_parts: Vec<Component> = to.components().filter(|c| !matches!(c, Component::CurDir)).collect();
    let common = from.iter().zip(&to_parts).take_while(|(a, b)| a == b).count();
    let mut path = String::new();
    for _ in common..from.len() {
        path.push_str("../");
    }
    let rest: PathBuf = to_parts[common..].iter().collect();
    path.push_str(&rest.display().to_string().replace('\\', "/"));
    path
}

#[cfg(test)]
mod tests {
    use super::relative;
    use std::path::Path;

    #[test]
    fn figures_relative_to_the_report() {
        assert_eq!(relative(Path::new("paper"), Path::new("results/figures")), "../results/figures");
        assert_eq!(relative(Path::new(""), Path::new("results/figures")), "results/figures");
        assert_eq!(relative(Path::new("a/b"), Path::new("r/f")), "../../r/f");
        assert_eq!(relative(Path::new("/tmp/x/paper"), Path::new("/tmp/x/results/figures")), "../results/figures");
        assert_eq!(relative(Path::new("paper"), Path::new("results/timing/a.h5")), "../results/timing/a.h5");
    }
}
