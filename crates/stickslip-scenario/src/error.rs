//! Typed errors: parsing (with field path, line and column) and validation (with field path).

use stickslip_core::ParamError;
use thiserror::Error;

/// Why a scenario could not be loaded or built.
#[derive(Debug, Error)]
pub enum ScenarioError {
    /// The file could not be read.
    #[error("cannot read scenario `{path}`: {source}")]
    Io {
        /// The path.
        path: String,
        /// The I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The TOML is malformed or does not match the format.
    #[error("{0}")]
    Parse(Box<ParseError>),
    /// The values are well-formed TOML but invalid (see [`BuildError`]).
    #[error("{origin}{}: {source}", line.map(|l| format!(":{l}")).unwrap_or_default())]
    Invalid {
        /// File name, or `<string>`.
        origin: String,
        /// 1-based line of the field (or of the nearest enclosing table found), when located.
        line: Option<usize>,
        /// What is wrong (see also [`ScenarioError::build_error`]).
        #[source]
        source: Box<BuildError>,
    },
}

/// Where and why the TOML parser rejected a scenario.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseError {
    /// File name, or `<string>`.
    pub origin: String,
    /// Dotted path of the offending field (e.g. `body[1].collider[0].density`), when known.
    pub field: Option<String>,
    /// 1-based line, when the parser knows it.
    pub line: Option<usize>,
    /// 1-based column, when the parser knows it.
    pub column: Option<usize>,
    /// The parser's message alone.
    pub message: String,
    /// The parser's full report (with the source line and a caret).
    pub rendered: String,
}

impl std::fmt::Display for ParseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.origin)?;
        if let Some(l) = self.line {
            write!(f, ":{l}")?;
            if let Some(c) = self.column {
                write!(f, ":{c}")?;
            }
        }
        if let Some(field) = &self.field {
            write!(f, ": in field `{field}`")?;
        }
        write!(f, ":\n{}", self.rendered.trim_end())
    }
}

impl std::error::Error for ParseError {}

impl ScenarioError {
    /// The offending field's dotted path, when known.
    pub fn field(&self) -> Option<&str> {
        match self {
            ScenarioError::Parse(p) => p.field.as_deref(),
            ScenarioError::Invalid { source, .. } => Some(source.field()),
            ScenarioError::Io { .. } => None,
        }
    }

    /// The validation error, for [`ScenarioError::Invalid`].
    pub fn build_error(&self) -> Option<&BuildError> {
        match self {
            ScenarioError::Invalid { source, .. } => Some(source),
            ScenarioError::Parse(_) => None,
            ScenarioError::Io { .. } => None,
        }
    }

    /// The 1-based line of the error, when known.
    pub fn line(&self) -> Option<usize> {
        match self {
            ScenarioError::Parse(p) => p.line,
            ScenarioError::Invalid { line, .. } => *line,
            ScenarioError::Io { .. } => None,
        }
    }
}

/// A scenario value that cannot be built into a world.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BuildError {
    /// A number is NaN or infinite, or outside its range.
    #[error("field `{field}`: {reason}")]
    InvalidValue {
        /// Dotted path of the field.
        field: String,
        /// What is wrong with it.
        reason: String,
    },
    /// A core parameter check failed.
    #[error("field `{field}`: {source}")]
    Param {
        /// Dotted path of the field.
        field: String,
        /// The core's error.
        #[source]
        source: ParamError,
    },
    /// A name refers to nothing.
    #[error("field `{field}`: unknown {what} `{name}`{}", known_list(known))]
    Unknown {
        /// Dotted path of the field.
        field: String,
        /// What kind of thing (`body`, `material`, `vibration`).
        what: &'static str,
        /// The name given.
        name: String,
        /// The names that exist.
        known: Vec<String>,
    },
    /// Two bodies share a name.
    #[error("field `{field}`: duplicate body name `{name}`")]
    DuplicateBody {
        /// Dotted path of the field.
        field: String,
        /// The name.
        name: String,
    },
    /// A driver acts on a body of the wrong kind.
    #[error("field `{field}`: a {driver} driver needs a {needs} body, `{body}` is {is}")]
    WrongBodyKind {
        /// Dotted path of the field.
        field: String,
        /// Driver kind.
        driver: &'static str,
        /// What it needs.
        needs: &'static str,
        /// The body.
        body: String,
        /// What it is.
        is: &'static str,
    },
}

fn known_list(known: &[String]) -> String {
    if known.is_empty() {
        " (none defined)".to_string()
    } else {
        format!(" (known: {})", known.join(", "))
    }
}

impl BuildError {
    /// The offending field's dotted path.
    pub fn field(&self) -> &str {
        match self {
            BuildError::InvalidValue { field, .. }
            | BuildError::Param { field, .. }
            | BuildError::Unknown { field, .. }
            | BuildError::DuplicateBody { field, .. }
            | BuildError::WrongBodyKind { field, .. } => field,
        }
    }
}

/// 1-based (line, column) of byte offset `at` in `text`.
pub(crate) fn line_col(text: &str, at: usize) -> (usize, usize) {
    let at = at.min(text.len());
    let before = &text[..text.floor_char_boundary(at)];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

pub(crate) fn parse_error(
    origin: &str,
    text: &str,
    err: serde_path_to_error::Error<toml::de::Error>,
) -> ScenarioError {
    let path = err.path().to_string();
    let inner = err.into_inner();
    let (line, column) = match inner.span() {
        Some(span) => {
            let (l, c) = line_col(text, span.start);
            (Some(l), Some(c))
        }
        None => (None, None),
    };
    // serde_path_to_error prints `.` for the root.
    let field = (!path.is_empty() && path != ".").then_some(path);
    ScenarioError::Parse(Box::new(ParseError {
        origin: origin.to_string(),
        field,
        line,
        column,
        message: inner.message().to_string(),
        rendered: inner.to_string(),
    }))
}

pub(crate) fn syntax_error(origin: &str, text: &str, inner: toml::de::Error) -> ScenarioError {
    let (line, column) = match inner.span() {
        Some(span) => {
            let (l, c) = line_col(text, span.start);
            (Some(l), Some(c))
        }
        None => (None, None),
    };
    ScenarioError::Parse(Box::new(ParseError {
        origin: origin.to_string(),
        field: None,
        line,
        column,
        message: inner.message().to_string(),
        rendered: inner.to_string(),
    }))
}

/// 1-based (line, column) of a dotted field path such as `body[1].collider[0].density` in the
/// TOML `text`: of the field itself, else of the deepest enclosing value that exists.
pub(crate) fn locate(text: &str, field: &str) -> Option<(usize, usize)> {
    let root = toml::de::DeTable::parse(text).ok()?;
    let root = toml::de::DeValue::Table(root.into_inner());
    let mut cur = &root;
    let mut span = None;
    'path: for seg in field.split('.') {
        let (key, indices) = match seg.find('[') {
            Some(i) => (&seg[..i], &seg[i..]),
            None => (seg, ""),
        };
        if !key.is_empty() {
            let Some(v) = cur.get(key) else { break };
            span = Some(v.span());
            cur = v.get_ref();
        }
        for idx in indices.split(']').filter_map(|p| p.strip_prefix('[')) {
            let Some(v) = idx.parse::<usize>().ok().and_then(|i| cur.get(i)) else {
                break 'path;
            };
            span = Some(v.span());
            cur = v.get_ref();
        }
    }
    span.map(|s| line_col(text, s.start))
}
