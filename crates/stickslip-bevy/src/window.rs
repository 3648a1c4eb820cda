//! Windowed apps and their pictures (feature `window`): the command line of stickslip's
//! windowed examples (`--screenshot PATH --frames N`), the check for a display, and
//! [`ScreenshotAndExit`], which saves the window at a given frame and exits (how CI takes the
//! examples' pictures under Xvfb).

use bevy::diagnostic::FrameCount;
use bevy::prelude::*;
use bevy::render::view::screenshot::{Screenshot, ScreenshotCaptured, save_to_disk};
use bevy::time::TimeUpdateStrategy;
use std::time::Duration;

/// The size of every windowed app's window (px): CI's screenshots are taken at it.
pub const WINDOW_SIZE: (u32, u32) = (1280, 720);

/// bevy's default plugins with the primary window of stickslip's windowed apps (`title`,
/// [`WINDOW_SIZE`]) and their dark background.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WindowedApp {
    /// The window's title.
    pub title: String,
}

impl WindowedApp {
    /// The windowed app titled `title`.
    pub fn new(title: impl Into<String>) -> Self {
        WindowedApp {
            title: title.into(),
        }
    }
}

impl Plugin for WindowedApp {
    fn build(&self, app: &mut App) {
        app.add_plugins(DefaultPlugins.set(WindowPlugin {
            primary_window: Some(Window {
                title: self.title.clone(),
                resolution: WINDOW_SIZE.into(),
                ..default()
            }),
            ..default()
        }))
        .insert_resource(ClearColor(Color::srgb(0.09, 0.1, 0.12)));
    }
}

/// Frames after the requested one by which a screenshot that never arrived ends the run.
const PATIENCE: u32 = 300;

/// Saves the primary window to `path` (PNG) at frame `frame`, then exits the app; a
/// screenshot that never arrives ends the run with an error instead of hanging it. As a
/// plugin it also makes every frame advance 1/30 s of time, however slow the renderer, so that
/// the picture is the same on every machine.
#[derive(Resource, Clone, Debug, PartialEq, Eq)]
pub struct ScreenshotAndExit {
    /// Where the PNG goes.
    pub path: String,
    /// The frame it shows (≥ 1).
    pub frame: u32,
}

impl ScreenshotAndExit {
    /// Takes `--screenshot PATH` and `--frames N` (default `frames`) out of `args`: the
    /// screenshot (`None` without `--screenshot`) and the other arguments, in order. An option
    /// without its value, a frame count that is not a number, or another `--` option is an
    /// error.
    pub fn from_args(
        args: impl IntoIterator<Item = String>,
        frames: u32,
    ) -> Result<(Option<ScreenshotAndExit>, Vec<String>), String> {
        let (mut path, mut frame, mut rest) = (None, frames, Vec::new());
        let mut args = args.into_iter();
        while let Some(arg) = args.next() {
            match arg.as_str() {
                "--screenshot" => path = Some(args.next().ok_or("--screenshot needs a path")?),
                "--frames" => {
                    let n = args.next().ok_or("--frames needs a number")?;
                    frame = n
                        .parse()
                        .map_err(|_| format!("--frames: not a number: {n}"))?;
                }
                other if other.starts_with("--") => {
                    return Err(format!("unknown option {other}"));
                }
                _ => rest.push(arg),
            }
        }
        let shot = path.map(|path| ScreenshotAndExit {
            path,
            frame: frame.max(1),
        });
        Ok((shot, rest))
    }
}

impl Plugin for ScreenshotAndExit {
    fn build(&self, app: &mut App) {
        app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            1.0 / 30.0,
        )))
        .insert_resource(self.clone())
        .add_systems(Last, shot_and_exit);
    }
}

fn shot_and_exit(
    mut commands: Commands,
    frames: Res<FrameCount>,
    shot: Res<ScreenshotAndExit>,
    mut exit: MessageWriter<AppExit>,
) {
    if frames.0 == shot.frame {
        let path = shot.path.clone();
        commands.spawn(Screenshot::primary_window()).observe(
            move |captured: On<ScreenshotCaptured>, mut exit: MessageWriter<AppExit>| {
                save_to_disk(path.clone())(captured);
                info!("saved {path}");
                exit.write(AppExit::Success);
            },
        );
    }
    if frames.0 > shot.frame + PATIENCE {
        error!("no screenshot {PATIENCE} frames after it was requested");
        exit.write(AppExit::error());
    }
}

/// The command line of a windowed app: `--screenshot PATH --frames N` (default `frames`) and
/// at most `files` other arguments, which it returns; and a display to open the window on.
/// `None` when either is missing: it has said why on standard error, with `usage`.
pub fn command_line(
    usage: &str,
    frames: u32,
    files: usize,
) -> Option<(Option<ScreenshotAndExit>, Vec<String>)> {
    match ScreenshotAndExit::from_args(std::env::args().skip(1), frames) {
        Ok((shot, rest)) if rest.len() <= files => has_display(usage).then_some((shot, rest)),
        Ok((_, rest)) => {
            eprintln!("unexpected arguments {rest:?}\nusage: {usage}");
            None
        }
        Err(e) => {
            eprintln!("{e}\nusage: {usage}");
            None
        }
    }
}

/// Whether a window can open here (an X11 or Wayland display); if not, it says how to run the
/// app `usage` under Xvfb, on standard error.
pub fn has_display(usage: &str) -> bool {
    if std::env::var_os("DISPLAY").is_some() || std::env::var_os("WAYLAND_DISPLAY").is_some() {
        return true;
    }
    eprintln!(
        "no display: run this app on a desktop, or under Xvfb: \
         xvfb-run -a -s \"-screen 0 1280x720x24\" {usage}"
    );
    false
}

/// The heads-up display of a windowed app: a text box at the window's top left corner, on a
/// translucent backing; the app's own system writes its `Text` each frame.
#[derive(Component, Debug, Default, Clone, Copy)]
pub struct Hud;

/// A [`Hud`] text box to spawn (15 px text, 8 px from the corner and of padding).
pub fn hud_box() -> impl Bundle {
    (
        Hud,
        Text::new(""),
        TextFont {
            font_size: FontSize::Px(15.0),
            ..default()
        },
        Node {
            position_type: PositionType::Absolute,
            top: px(8),
            left: px(8),
            padding: UiRect::all(px(8)),
            ..default()
        },
        BackgroundColor(Color::srgba(0.0, 0.0, 0.0, 0.55)),
    )
}

/// A caption to spawn and place over the scene (17 px, light text, absolutely positioned: the
/// app's own system sets its `Node`'s `left` and `top` from where its subject is on screen).
pub fn caption(text: impl Into<String>) -> impl Bundle {
    (
        Text::new(text.into()),
        TextFont {
            font_size: FontSize::Px(17.0),
            ..default()
        },
        TextColor(Color::srgb(0.9, 0.92, 0.95)),
        Node {
            position_type: PositionType::Absolute,
            ..default()
        },
    )
}

/// Time controls every windowed app has: Space pauses and resumes, S toggles slow motion
/// (a tenth of real time). Add it to `Update`.
pub fn time_keys(keys: Res<ButtonInput<KeyCode>>, mut time: ResMut<Time<Virtual>>) {
    if keys.just_pressed(KeyCode::Space) {
        time.toggle();
    }
    if keys.just_pressed(KeyCode::KeyS) {
        let slow = time.relative_speed() < 1.0;
        time.set_relative_speed(if slow { 1.0 } else { 0.1 });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(s: &str) -> Vec<String> {
        s.split_whitespace().map(String::from).collect()
    }

    #[test]
    fn the_screenshot_options_come_out_and_the_rest_stays() {
        let (shot, rest) =
            ScreenshotAndExit::from_args(args("a.toml --screenshot x.png --frames 7"), 120)
                .unwrap();
        assert_eq!(
            shot,
            Some(ScreenshotAndExit {
                path: "x.png".into(),
                frame: 7
            })
        );
        assert_eq!(rest, args("a.toml"));
        let (shot, rest) = ScreenshotAndExit::from_args(args("--screenshot y.png"), 90).unwrap();
        assert_eq!(shot.map(|s| s.frame), Some(90));
        assert!(rest.is_empty());
        assert_eq!(
            ScreenshotAndExit::from_args(args(""), 90).unwrap(),
            (None, vec![])
        );
        assert_eq!(
            ScreenshotAndExit::from_args(args("--frames 0 --screenshot z.png"), 90)
                .unwrap()
                .0
                .map(|s| s.frame),
            Some(1)
        );
        for bad in ["--screenshot", "--frames", "--frames many", "--fast"] {
            assert!(
                ScreenshotAndExit::from_args(args(bad), 90).is_err(),
                "{bad}"
            );
        }
    }
}
