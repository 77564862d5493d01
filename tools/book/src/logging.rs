//! A minimal `tracing` subscriber: mdBook 0.5 logs through `tracing`; this prints its WARN and
//! ERROR events to stderr (`warning: …` / `error: …`) and counts the errors so that the build
//! can fail on them. Everything below WARN is disabled at the callsite.

use std::fmt::{self, Write as _};
use std::sync::atomic::{AtomicUsize, Ordering};

use tracing::field::{Field, Visit};
use tracing::level_filters::LevelFilter;
use tracing::span::{Attributes, Id, Record};
use tracing::{Event, Level, Metadata, Subscriber};

static ERRORS: AtomicUsize = AtomicUsize::new(0);

struct StderrLogger;

/// Collects an event's fields into one line: the message, then ` key=value` for the others.
#[derive(Default)]
struct Line(String);

impl Visit for Line {
    fn record_debug(&mut self, field: &Field, value: &dyn fmt::Debug) {
        if field.name() == "message" {
            let _ = write!(self.0, "{value:?}");
        } else {
            let _ = write!(self.0, " {}={value:?}", field.name());
        }
    }

    fn record_str(&mut self, field: &Field, value: &str) {
        if field.name() == "message" {
            self.0.push_str(value);
        } else {
            let _ = write!(self.0, " {}={value}", field.name());
        }
    }
}

impl Subscriber for StderrLogger {
    fn enabled(&self, metadata: &Metadata<'_>) -> bool {
        metadata.is_event() && *metadata.level() <= Level::WARN
    }

    fn max_level_hint(&self) -> Option<LevelFilter> {
        Some(LevelFilter::WARN)
    }

    fn new_span(&self, _: &Attributes<'_>) -> Id {
        Id::from_u64(1)
    }

    fn record(&self, _: &Id, _: &Record) {}

    fn record_follows_from(&self, _: &Id, _: &Id) {}

    fn event(&self, event: &Event<'_>) {
        let mut line = Line::default();
        event.record(&mut line);
        let level = *event.metadata().level();
        if level == Level::ERROR {
            ERRORS.fetch_add(1, Ordering::Relaxed);
            eprintln!("error: {}", line.0);
        } else {
            eprintln!("warning: {}", line.0);
        }
    }

    fn enter(&self, _: &Id) {}

    fn exit(&self, _: &Id) {}
}

/// Installs the stderr logger as the global `tracing` subscriber (once; later calls do nothing).
pub fn init() {
    let _ = tracing::subscriber::set_global_default(StderrLogger);
}

/// Number of ERROR events logged so far (by mdBook or a preprocessor).
pub fn error_count() -> usize {
    ERRORS.load(Ordering::Relaxed)
}
