//! The examples' command line (`examples/common/options.rs`): defaults are the example's,
//! every option parses, mistakes are errors (never panics), and arbitrary argument lists
//! never panic.

use crate::common;
use crate::options;

use clap::error::ErrorKind;
use common::config;
use options::{Example, Options};
use proptest::prelude::*;
use raytrace::advice::Precision;
// The limit the examples share with the binary.
use raytrace::cli::MAX_THREADS;
use raytrace::image::Encoding;
use std::path::PathBuf;

const REGRESSIONS: &str = "proptest-regressions/example_options.txt";

fn demo() -> Example {
    Example {
        name: "demo",
        about: "A demo.",
        defaults: Options::defaults(800, 4, 10),
    }
}

/// Parses `args` after a program name, as the examples do.
fn parse(args: &[&str]) -> Result<Options, clap::Error> {
    demo().try_parse_from(std::iter::once("demo").chain(args.iter().copied()))
}

#[test]
fn defaults_are_the_examples() {
    assert_eq!(parse(&[]).unwrap(), Options::defaults(800, 4, 10));
    let mut defaults = Options::defaults(400, 1, 50);
    defaults.seed = 9;
    defaults.precision = Precision::F32;
    defaults.encoding = Encoding::Linear;
    defaults.out = "report/figures".into();
    let example = Example {
        defaults: defaults.clone(),
        ..demo()
    };
    assert_eq!(example.try_parse_from(["demo"]).unwrap(), defaults);
}

#[test]
fn every_option_parses() {
    let o = parse(&[
        "--width",
        "400",
        "--spp=16",
        "--max-depth",
        "0",
        "--seed",
        "7",
        "--precision",
        "f32",
        "--threads",
        "2",
        "--encoding",
        "linear",
        "--out",
        "/tmp/x",
    ])
    .unwrap();
    assert_eq!((o.width, o.spp, o.max_depth, o.seed), (400, 16, 0, 7));
    assert_eq!(
        (o.precision, o.threads, o.encoding),
        (Precision::F32, Some(2), Encoding::Linear)
    );
    assert_eq!(o.out, PathBuf::from("/tmp/x"));
    let o = parse(&["--threads", &MAX_THREADS.to_string(), "--encoding", "srgb"]).unwrap();
    assert_eq!((o.threads, o.encoding), (Some(MAX_THREADS), Encoding::Srgb));
}

#[test]
fn help_shows_the_about_text_and_the_defaults() {
    let err = parse(&["--help"]).unwrap_err();
    assert_eq!(err.kind(), ErrorKind::DisplayHelp);
    let text = err.to_string();
    assert!(text.starts_with("A demo."), "{text}");
    for want in [
        "--width <W>",
        "[default: 800]",
        "--spp <N>",
        "[default: 4]",
        "--max-depth <D>",
        "[default: 10]",
        "--seed <S>",
        "--precision <P>",
        "[default: f64]",
        "--threads <T>",
        "--encoding <E>",
        "[default: srgb]",
        "--out <DIR>",
        "[default: output]",
    ] {
        assert!(text.contains(want), "{want} missing from help:\n{text}");
    }
}

#[test]
fn mistakes_are_errors_that_say_what_was_wrong() {
    for (args, kind, want) in [
        (&["--bogus"][..], ErrorKind::UnknownArgument, "--bogus"),
        (&["800"], ErrorKind::UnknownArgument, "800"),
        (&["--width"], ErrorKind::InvalidValue, "--width"),
        (&["--width", "0"], ErrorKind::ValueValidation, "at least 1"),
        (&["--width", "wide"], ErrorKind::ValueValidation, "whole number"),
        (&["--spp", "0"], ErrorKind::ValueValidation, "at least 1"),
        (&["--spp", "1.5"], ErrorKind::ValueValidation, "whole number"),
        (&["--spp", "5000000000"], ErrorKind::ValueValidation, "too large"),
        (&["--max-depth", "x"], ErrorKind::ValueValidation, "--max-depth"),
        (
            &["--seed", "18446744073709551616"],
            ErrorKind::ValueValidation,
            "--seed",
        ),
        (&["--threads", "0"], ErrorKind::ValueValidation, "from 1 to 256"),
        (&["--threads", "257"], ErrorKind::ValueValidation, "from 1 to 256"),
        (
            &["--threads", "100000"],
            ErrorKind::ValueValidation,
            "from 1 to 256",
        ),
        (&["--precision", "f16"], ErrorKind::InvalidValue, "f32, f64"),
        (&["--encoding", "gamma"], ErrorKind::InvalidValue, "srgb, linear"),
        (&["--out"], ErrorKind::InvalidValue, "--out"),
    ] {
        let err = parse(args).unwrap_err();
        let text = err.to_string();
        assert_eq!(err.kind(), kind, "{args:?}: {text}");
        assert!(text.contains(want), "{args:?}: {text}");
        assert!(text.contains("--help"), "{args:?}: {text}");
        // clap exits with 2 on a usage mistake.
        assert_eq!(err.exit_code(), 2, "{args:?}");
    }
}

/// One command-line word: an option, a value, both joined by `=`, or anything at all.
fn arg() -> impl Strategy<Value = String> {
    let key = prop::sample::select(vec![
        "--width",
        "--spp",
        "--max-depth",
        "--seed",
        "--precision",
        "--threads",
        "--encoding",
        "--out",
        "--help",
        "-h",
        "--bogus",
        "--",
        "-",
        "",
        "--width=",
    ]);
    let value = prop_oneof![
        3 => prop::sample::select(vec![
            "0", "1", "800", "256", "257", "-3", "+5", " 5", "5 ", "f32", "f64", "F32", "srgb",
            "linear", "=", "", "4294967296", "18446744073709551616", "99999999999999999999", "1e3", "٣",
        ])
        .prop_map(String::from),
        1 => any::<u64>().prop_map(|n| n.to_string()),
        1 => any::<String>(),
    ];
    prop_oneof![
        3 => key.clone().prop_map(String::from),
        3 => value.clone(),
        2 => (key, value).prop_map(|(k, v)| format!("{k}={v}")),
    ]
}

proptest! {
    #![proptest_config(config(10_000, 0xBAD_C11, REGRESSIONS))]

    /// Parsing never panics, and what it returns is consistent: options it accepts are
    /// usable (width and samples at least 1, threads from 1 to 256), and an error is help
    /// or points to `--help`.
    #[test]
    fn arbitrary_arguments_never_panic(args in prop::collection::vec(arg(), 0..10)) {
        let argv: Vec<&str> = args.iter().map(String::as_str).collect();
        match parse(&argv) {
            Ok(o) => prop_assert!(
                o.width >= 1 && o.spp >= 1 && o.threads.is_none_or(|t| (1..=MAX_THREADS).contains(&t)),
                "{args:?} gave {o:?}"
            ),
            Err(e) if e.kind() == ErrorKind::DisplayHelp => {
                prop_assert!(e.to_string().contains("--width"), "{e}");
            }
            Err(e) => prop_assert!(e.to_string().contains("--help"), "{args:?}: {e}"),
        }
    }
}
