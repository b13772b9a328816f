/// @file
/// @brief The editor's tracking (docs/editor.md, "Tracking"): the document's camera and tracks as
/// undo steps and the anchor's checks; a subject tracked, cancelled and corrected on the worker
/// on an x264 clip of a patch crossing the seam; the buttons pressed through the desktop sim's
/// clicks and a headset's left trigger.
#include <gtest/gtest.h>

#include <thread>

#include "app/editor/editor.h"
#include "editor_scripts.h"
#include "editor_test_util.h"
#include "effects/anchor.h"
#include "effects/direction_angle.h"
#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "tests/app/command_test_util.h"
#include "tests/app/track_test_util.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {
namespace {

using effects::Anchor;
using effects::Direction;
using effects::EffectType;

effects::SubjectTrack line_track(const std::string& name, std::int64_t frames, double az0) {
  effects::SubjectTrack t{name, {}};
  for (std::int64_t f = 0; f < frames; ++f)
    t.points.push_back({f, {az0 + static_cast<double>(f), 0.0}, f == 3 ? 0.0 : 0.9});
  return t;
}

effects::CameraMotion still_camera(std::int64_t frames) {
  return {effects::CameraMotion::Source::Given,
          std::vector<effects::Quat>(static_cast<std::size_t>(frames), {1.0, 0.0, 0.0, 0.0})};
}

TEST(TrackDocument, ATrackIsOneUndoStepAndUndoGivesBackTheSidecar) {
  Document doc(test::empty_sidecar(10), DocumentOptions{{.async = false}});
  const std::string before = io::format_sidecar(doc.sidecar());
  doc.put_track(line_track("walker", 10, 0.0));
  ASSERT_NE(doc.track("walker"), nullptr);
  EXPECT_EQ(doc.sidecar().tracks.size(), 1u);
  EXPECT_EQ(doc.undo_stack().undo_size(), 1u);
  EXPECT_EQ(doc.undo_stack().next_undo_label(), "track walker");
  // Replacing it (a correction) is one more step; undo gives the first track back.
  doc.put_track(line_track("walker", 10, 20.0));
  EXPECT_EQ(doc.undo_stack().next_undo_label(), "re-track walker");
  EXPECT_EQ(doc.track("walker")->points[0].direction.azimuth_deg, 20.0);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.track("walker")->points[0].direction.azimuth_deg, 0.0);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(io::format_sidecar(doc.sidecar()), before);
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.tracks().size(), 1u);
  // Bad tracks change nothing.
  EXPECT_THROW(doc.put_track(line_track("no spaces", 10, 0.0)), io::InputError);
  EXPECT_THROW(doc.put_track(line_track("long", 11, 0.0)), io::InputError);
  EXPECT_EQ(doc.undo_stack().undo_size(), 1u);
}

TEST(TrackDocument, DeletingATrackPutsItsEffectsBackOnTheVideoInOneUndoStep) {
  Document doc(test::empty_sidecar(10), DocumentOptions{{.async = false}});
  doc.put_track(line_track("walker", 10, 0.0));
  doc.put_track(line_track("dog", 10, 50.0));
  doc.set_anchor(EffectType::Saturation, {Anchor::Kind::Track, "walker"});
  doc.set_anchor(EffectType::Exposure, {Anchor::Kind::Track, "dog"});
  // A keyframe at frame 5 in the walker's frame.
  doc.add_keyframe(EffectType::Saturation, effects::Keyframe{Direction{5.0, 0.0}, 5, {2.0}});
  const effects::Keyframe anchored = doc.keyframes(EffectType::Saturation).front();
  // Where it shows in the video at its frame: the walker's frame undone.
  const Direction shown =
      effects::anchor_frames({Anchor::Kind::Track, "walker"}, nullptr, doc.tracks())
          .unapply(anchored.direction, anchored.frame);
  ASSERT_GT(effects::angle_between_deg(shown, anchored.direction), 1.0);  // the anchor matters
  const std::string before = io::format_sidecar(doc.sidecar());
  const std::size_t steps = doc.undo_stack().undo_size();

  EXPECT_THROW(doc.remove_track("cat"), io::InputError);
  EXPECT_EQ(doc.remove_track("walker"), 1);
  EXPECT_EQ(doc.track("walker"), nullptr);
  ASSERT_NE(doc.track("dog"), nullptr);
  EXPECT_TRUE(doc.anchor(EffectType::Saturation).is_video());
  EXPECT_EQ(effects::anchor_name(doc.anchor(EffectType::Exposure)), "track:dog");
  // The keyframe stays where it showed at its frame.
  const effects::Keyframe& k = doc.keyframes(EffectType::Saturation).front();
  EXPECT_NEAR(effects::angle_between_deg(k.direction, shown), 0.0, 1e-9);
  EXPECT_EQ(k.frame, 5);
  EXPECT_EQ(doc.undo_stack().undo_size(), steps + 1);
  EXPECT_EQ(doc.undo_stack().next_undo_label(), "delete track walker");
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(io::format_sidecar(doc.sidecar()), before);
  EXPECT_EQ(doc.keyframes(EffectType::Saturation).front(), anchored);
  // A track nothing is anchored to goes alone.
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.remove_track("dog"), 1);
  EXPECT_TRUE(doc.tracks().empty());
}

TEST(TrackDocument, RenamingATrackRenamesEveryAnchorNamingItInOneUndoStep) {
  Document doc(test::empty_sidecar(10), DocumentOptions{{.async = false}});
  doc.put_track(line_track("walker", 10, 0.0));
  doc.put_track(line_track("dog", 10, 50.0));
  doc.set_anchor(EffectType::Saturation, {Anchor::Kind::Track, "walker"});
  doc.set_anchor(EffectType::Contrast, {Anchor::Kind::Track, "walker"});
  doc.set_anchor(EffectType::Exposure, {Anchor::Kind::Track, "dog"});
  doc.add_keyframe(EffectType::Saturation, effects::Keyframe{Direction{5.0, 0.0}, 5, {2.0}});
  const std::vector<effects::Keyframe> keyframes = doc.keyframes(EffectType::Saturation);
  const std::string before = io::format_sidecar(doc.sidecar());
  io::Sidecar renamed = doc.sidecar();  // as `vdfx track rename` would write it, below
  const std::size_t steps = doc.undo_stack().undo_size();

  // Refused, the document as it was: no such track, a name taken, not a name.
  EXPECT_THROW(doc.rename_track("cat", "alice"), io::InputError);
  EXPECT_THROW(doc.rename_track("walker", "dog"), io::InputError);
  EXPECT_THROW(doc.rename_track("walker", "al ice"), io::InputError);
  EXPECT_THROW(doc.rename_track("walker", ""), io::InputError);
  EXPECT_EQ(io::format_sidecar(doc.sidecar()), before);
  EXPECT_EQ(doc.undo_stack().undo_size(), steps);

  EXPECT_EQ(doc.rename_track("walker", "Alice_2"), 2);
  ASSERT_EQ(doc.tracks().size(), 2u);
  EXPECT_EQ(doc.tracks()[0].name, "Alice_2");  // in the old one's place
  EXPECT_EQ(doc.tracks()[0].points, line_track("x", 10, 0.0).points);
  EXPECT_EQ(doc.track("walker"), nullptr);
  EXPECT_EQ(effects::anchor_name(doc.anchor(EffectType::Saturation)), "track:Alice_2");
  EXPECT_EQ(effects::anchor_name(doc.anchor(EffectType::Contrast)), "track:Alice_2");
  EXPECT_EQ(effects::anchor_name(doc.anchor(EffectType::Exposure)), "track:dog");
  EXPECT_EQ(doc.keyframes(EffectType::Saturation), keyframes);  // not one bit moved
  EXPECT_EQ(doc.undo_stack().undo_size(), steps + 1);
  EXPECT_EQ(doc.undo_stack().next_undo_label(), "rename track walker to Alice_2");
  // The sidecar is the one `vdfx track rename` writes.
  io::rename_track(renamed, "walker", "Alice_2", "before.vdfx.json");
  EXPECT_EQ(io::format_sidecar(doc.sidecar()), io::format_sidecar(renamed));
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(io::format_sidecar(doc.sidecar()), before);
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(effects::anchor_name(doc.anchor(EffectType::Contrast)), "track:Alice_2");
}

TEST(TrackDocument, TheCameraIsOneUndoStepWithOneOrientationPerFrame) {
  Document doc(test::empty_sidecar(10), DocumentOptions{{.async = false}});
  EXPECT_THROW(doc.set_camera(still_camera(9)), io::InputError);
  EXPECT_FALSE(doc.camera());
  doc.set_camera(still_camera(10));
  ASSERT_TRUE(doc.camera());
  EXPECT_TRUE(doc.sidecar().camera.has_value());
  EXPECT_EQ(doc.undo_stack().next_undo_label(), "track camera");
  ASSERT_TRUE(doc.undo());
  EXPECT_FALSE(doc.camera());
  EXPECT_FALSE(doc.sidecar().camera.has_value());
}

TEST(TrackDocument, AnAnchorNeedsWhatItNames) {
  Editor ed(test::empty_sidecar(10), DocumentOptions{{.async = false}}, EditorOptions{});
  ed.select_effect(EffectType::Saturation);
  // The contract's checks: world needs the camera, a track anchor its track.
  EXPECT_THROW(ed.document().set_anchor(EffectType::Saturation, {Anchor::Kind::World, ""}),
               io::InputError);
  EXPECT_FALSE(ed.set_anchor({Anchor::Kind::World, ""}));
  EXPECT_NE(ed.hud_message().find("needs the camera's motion"), std::string::npos)
      << ed.hud_message();
  EXPECT_FALSE(ed.set_anchor({Anchor::Kind::Track, "walker"}));
  EXPECT_FALSE(ed.document().undo_stack().can_undo());
  // The button cycles through what there is: video, world (with a camera), each track.
  ed.next_anchor();
  EXPECT_TRUE(ed.document().anchor(EffectType::Saturation).is_video());  // nothing else yet
  ed.document().set_camera(still_camera(10));
  ed.document().put_track(line_track("walker", 10, 0.0));
  ed.next_anchor();
  EXPECT_EQ(effects::anchor_name(ed.document().anchor(EffectType::Saturation)), "world");
  ed.next_anchor();
  EXPECT_EQ(effects::anchor_name(ed.document().anchor(EffectType::Saturation)), "track:walker");
  EXPECT_EQ(ed.document().sidecar().effects.size(), 1u);  // its anchor is written
  ed.update(test::looking(0.0, 0.0, 1), 1);
  EXPECT_EQ(ed.ui().track_section().anchor_button().label(), "Anchor: walker");
  EXPECT_EQ(ed.shown_track(), ed.document().track("walker"));
  ed.next_anchor();
  EXPECT_TRUE(ed.document().anchor(EffectType::Saturation).is_video());
  // Each anchor change was one step: undo goes back through them.
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(effects::anchor_name(ed.document().anchor(EffectType::Saturation)), "track:walker");
}

TEST(TrackCorrection, KeepsTheEarlierFramesItSawAndTakesTheRestFromTheNewRun) {
  const effects::SubjectTrack old_track = line_track("t", 10, 0.0);  // held at frame 3
  const effects::SubjectTrack fresh = line_track("t", 10, 50.0);
  const effects::SubjectTrack merged = merge_correction(old_track, fresh, 5);
  ASSERT_EQ(merged.points.size(), 10u);
  for (std::size_t f = 0; f < 10; ++f) {
    const bool from_old = f < 5 && f != 3;  // frame 3 was held by the old track
    EXPECT_EQ(merged.points[f], from_old ? old_track.points[f] : fresh.points[f]) << f;
  }
}

// ---- on a clip: the patch crossing the seam at altitude 10 (app/bench/track_clips.h)

constexpr int kFrames = 30;

struct Clip {
  app::testing::SubjectClip clip;
  Direction at(int frame) const {
    return effects::from_unit(clip.truth[static_cast<std::size_t>(frame)].centre());
  }
};

const Clip& seam_clip() {
  static const Clip c{app::testing::write_subject_clip(app::testing::test_dir() / "seam.mp4",
                                                       bench::SubjectMotion::Seam, kFrames, 512)};
  return c;
}

EditorOptions on_clip(bool async, PanelLayout layout = PanelLayout::Hands) {
  EditorOptions o;
  o.video = seam_clip().clip.path;
  o.async_suggestions = async;
  o.visuals.async = false;
  o.layout = layout;
  return o;
}

io::Sidecar clip_sidecar() {
  return io::new_sidecar({seam_clip().clip.path.string(), 30.0, kFrames, 512, 256});
}

/// Looks at `d` (the head's direction is the view centre the buttons track from).
void look_at(Editor& ed, const Direction& d, std::int64_t t) {
  ed.update(test::looking(d.azimuth_deg, d.altitude_deg, t), t);
}

TEST(EditorTrack, ASubjectIsTrackedOnTheWorkerWithProgressAsOneUndoStep) {
  Editor ed(clip_sidecar(), DocumentOptions{{.async = false}}, on_clip(true));
  ed.seek(10);
  look_at(ed, seam_clip().at(10), 1);
  ed.track_subject();
  ASSERT_TRUE(ed.tracking_progress().has_value());
  // The progress moves while it runs, and the button says it cancels.
  ed.update(test::looking(0, 0, 2), 2);
  EXPECT_EQ(ed.ui().track_section().subject_button().label().rfind("Cancel", 0), 0u)
      << ed.ui().track_section().subject_button().label();
  EXPECT_FALSE(ed.ui().track_section().camera_button().enabled());
  double seen_between = -1.0;
  for (int i = 0; i < 20000 && ed.tracking_progress(); ++i) {
    const double p = *ed.tracking_progress();
    if (p > 0.0 && p < 1.0) seen_between = p;
    ed.update(test::looking(0, 0, 3 + i), 3 + i);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(ed.wait_for_tracking(std::chrono::seconds(120)));
  EXPECT_GT(seen_between, 0.0) << "no progress reported between 0 and 1";
  const effects::SubjectTrack* t = ed.document().track("subject1");
  ASSERT_NE(t, nullptr) << ed.hud_message();
  ASSERT_EQ(t->points.size(), static_cast<std::size_t>(kFrames));
  for (int f = 0; f < kFrames; ++f)
    EXPECT_LT(effects::angle_between_deg(t->points[f].direction, seam_clip().at(f)), 2.0) << f;
  EXPECT_EQ(ed.document().undo_stack().undo_size(), 1u);
  EXPECT_EQ(ed.document().undo_stack().next_undo_label(), "track subject1");
  // Drawn in the view (the marker at the current frame) and on the timeline (its span).
  ed.seek(20);
  ed.update(test::looking(0, 0, 30000), 30000);
  ASSERT_TRUE(ed.ui().track_marker().direction());
  EXPECT_LT(effects::angle_between_deg(*ed.ui().track_marker().direction(), seam_clip().at(20)),
            2.0);
  EXPECT_TRUE(ed.ui().track_marker().panel().visible());
  EXPECT_EQ(ed.ui().strip().track_band().first, 0);
  EXPECT_EQ(ed.ui().strip().track_band().last, kFrames - 1);
  // One undo removes it, and the marker and band go with it.
  ASSERT_TRUE(ed.undo());
  ed.update(test::looking(0, 0, 30001), 30001);
  EXPECT_TRUE(ed.document().tracks().empty());
  EXPECT_FALSE(ed.ui().track_marker().panel().visible());
  EXPECT_EQ(ed.ui().strip().track_band().first, -1);
}

TEST(EditorTrack, CancellingLeavesTheDocumentAsItWas) {
  Editor ed(clip_sidecar(), DocumentOptions{{.async = false}}, on_clip(true));
  const std::string before = io::format_sidecar(ed.document().sidecar());
  ed.track_camera();
  ASSERT_TRUE(ed.tracking_progress().has_value());
  ed.track_subject();  // any tracking button cancels the run
  ASSERT_TRUE(ed.wait_for_tracking(std::chrono::seconds(120)));
  EXPECT_FALSE(ed.tracking_progress().has_value());
  EXPECT_EQ(io::format_sidecar(ed.document().sidecar()), before);
  EXPECT_FALSE(ed.document().undo_stack().can_undo());
  EXPECT_NE(ed.hud_message().find("cancelled, nothing changed"), std::string::npos)
      << ed.hud_message();
}

TEST(EditorTrack, ACorrectionReTracksFromThePointDroppedAsOneUndoStep) {
  Editor ed(clip_sidecar(), DocumentOptions{{.async = false}}, on_clip(false));
  // Started 25 degrees off the patch: the still background is followed instead.
  Direction wrong = seam_clip().at(0);
  wrong.altitude_deg += 25.0;
  look_at(ed, wrong, 1);
  ed.track_subject();
  const effects::SubjectTrack first = *ed.document().track("subject1");
  EXPECT_GT(effects::angle_between_deg(first.points[20].direction, seam_clip().at(20)), 10.0);
  // Dropped on the patch at frame 12: from there on it follows the patch.
  ed.seek(12);
  look_at(ed, seam_clip().at(12), 2);
  ed.correct_track();
  const effects::SubjectTrack* fixed = ed.document().track("subject1");
  ASSERT_NE(fixed, nullptr);
  for (int f = 12; f < kFrames; ++f)
    EXPECT_LT(effects::angle_between_deg(fixed->points[f].direction, seam_clip().at(f)), 2.0) << f;
  for (int f = 0; f < 12; ++f) {
    if (first.points[f].confidence > 0.0) {
      EXPECT_EQ(fixed->points[f], first.points[f]) << f;
    }
  }
  EXPECT_EQ(ed.document().undo_stack().undo_size(), 2u);
  EXPECT_EQ(ed.document().undo_stack().next_undo_label(), "re-track subject1");
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(*ed.document().track("subject1"), first);
}

// ---- the buttons, as a person presses them

/// The editor on the clip in the Desktop layout, its widgets clicked through the desktop sim.
struct DesktopClicks {
  DesktopClicks()
      : sim(xr::create_sim_backend({})),
        ed(clip_sidecar(), DocumentOptions{{.async = false}},
           on_clip(false, PanelLayout::Desktop)) {
    step();
  }
  void step() {
    for (int i = 0; i < 3; ++i, t += test::kFrameNs) ed.update(sim->poll(t), t);
  }
  void click(const char* panel, const ui::Widget& w) {
    const glm::dvec2 c = test::cursor_for(panel, w.rect().centre(), kFrames);
    sim->push_event(xr::MouseMoveEvent{c.x, c.y});
    sim->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, true});
    sim->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, false});
    step();
  }
  std::unique_ptr<xr::InputBackend> sim;
  Editor ed;
  std::int64_t t = 0;
};

TEST(EditorTrackPanel, DesktopClicksTrackTheCameraAndASubjectAndSetTheAnchor) {
  DesktopClicks d;
  Editor& ed = d.ed;
  const auto step = [&] { d.step(); };
  const auto click = [&](const ui::Button& b) { d.click(kViewsPanelId, b); };
  const TrackSection& s = ed.ui().track_section();
  EXPECT_FALSE(s.correct_button().enabled());  // nothing to correct yet
  click(s.camera_button());
  ASSERT_TRUE(ed.document().camera()) << ed.hud_message();
  EXPECT_EQ(ed.document().undo_stack().next_undo_label(), "track camera");
  click(s.subject_button());
  ASSERT_NE(ed.document().track("subject1"), nullptr) << ed.hud_message();
  EXPECT_TRUE(s.correct_button().enabled());
  EXPECT_EQ(s.correct_button().label(), "Correct subject1");
  click(s.anchor_button());  // video -> world
  EXPECT_EQ(effects::anchor_name(ed.document().anchor(EffectType::Exposure)), "world");
  click(s.anchor_button());  // world -> the track
  EXPECT_EQ(effects::anchor_name(ed.document().anchor(EffectType::Exposure)), "track:subject1");
  EXPECT_EQ(s.anchor_button().label(), "Anchor: subject1");
  EXPECT_EQ(ed.document().undo_stack().undo_size(), 4u);
  EXPECT_EQ(s.delete_button().label(), "Delete subject1");
  click(s.delete_button());
  EXPECT_EQ(ed.document().track("subject1"), nullptr) << ed.hud_message();
  EXPECT_TRUE(ed.document().anchor(EffectType::Exposure).is_video());
  EXPECT_EQ(ed.hud_message(),
            "deleted track subject1: 1 effect back on the video; undo brings it back");
  EXPECT_FALSE(s.delete_button().enabled());  // nothing left to delete
  EXPECT_EQ(s.delete_button().label(), "Delete track");
  EXPECT_EQ(s.anchor_button().label(), "Anchor: video");
  ASSERT_TRUE(ed.undo());
  step();
  EXPECT_NE(ed.document().track("subject1"), nullptr);
  EXPECT_EQ(s.anchor_button().label(), "Anchor: subject1");
}

TEST(EditorTrackPanel, DesktopClicksRenameATrackOnTheOnScreenKeys) {
  DesktopClicks d;
  Editor& ed = d.ed;
  const auto step = [&] { d.step(); };
  const auto click_on = [&](const char* panel, const ui::Widget& w) { d.click(panel, w); };
  const RenameKeyboard& keys = ed.ui().rename_keyboard();
  const auto type = [&](const std::string& key) {
    const ui::Button* b = keys.key(key);
    ASSERT_NE(b, nullptr) << key;
    click_on(kRenamePanelId, *b);
  };
  const TrackSection& s = ed.ui().track_section();
  EXPECT_FALSE(s.rename_button().enabled());  // no track yet
  click_on(kViewsPanelId, s.subject_button());
  ASSERT_NE(ed.document().track("subject1"), nullptr) << ed.hud_message();
  click_on(kViewsPanelId, s.anchor_button());  // video -> the track (no camera)
  ASSERT_EQ(effects::anchor_name(ed.document().anchor(EffectType::Exposure)), "track:subject1");
  EXPECT_FALSE(keys.panel().visible());
  EXPECT_EQ(s.rename_button().label(), "Rename subject1");

  // Opened on the name, typed over, and cancelled: nothing changes.
  click_on(kViewsPanelId, s.rename_button());
  EXPECT_TRUE(keys.panel().visible());
  type("Back");
  type("9");
  EXPECT_EQ(ed.track_view().rename.text, "subject9");
  click_on(kRenamePanelId, keys.cancel_button());
  EXPECT_FALSE(keys.panel().visible());
  EXPECT_NE(ed.document().track("subject1"), nullptr);
  const std::size_t steps = ed.document().undo_stack().undo_size();

  // Opened again: cleared, typed with Shift for the capital, and renamed.
  click_on(kViewsPanelId, s.rename_button());
  for (int i = 0; i < 8; ++i) type("Back");
  EXPECT_EQ(ed.track_view().rename.text, "");
  EXPECT_FALSE(keys.commit_button().enabled());  // not a name
  for (const char* k : {"Shift", "a", "Shift", "l", "i", "c", "e", "_", "2"}) type(k);
  EXPECT_EQ(ed.track_view().rename.text, "Alice_2");
  EXPECT_TRUE(keys.commit_button().enabled());
  click_on(kRenamePanelId, keys.commit_button());
  EXPECT_FALSE(keys.panel().visible());
  EXPECT_EQ(ed.document().track("subject1"), nullptr);
  ASSERT_NE(ed.document().track("Alice_2"), nullptr) << ed.hud_message();
  EXPECT_EQ(effects::anchor_name(ed.document().anchor(EffectType::Exposure)), "track:Alice_2");
  EXPECT_EQ(ed.hud_message(),
            "renamed track subject1 to Alice_2: 1 effect anchored to it; undo takes the old name "
            "back");
  EXPECT_EQ(ed.document().undo_stack().undo_size(), steps + 1);
  EXPECT_EQ(s.rename_button().label(), "Rename Alice_2");
  EXPECT_EQ(s.anchor_button().label(), "Anchor: Alice_2");
  ASSERT_TRUE(ed.undo());
  step();
  EXPECT_NE(ed.document().track("subject1"), nullptr);
  EXPECT_EQ(s.anchor_button().label(), "Anchor: subject1");
}

/// A tracked hand at `position` whose ray (and grip) points at `aim_at`'s centre on `panel`, or
/// along `rest` when there is none, with its trigger at `trigger`.
void aim_hand(xr::HandState& hand, const glm::dvec3& position, const glm::dquat& rest,
              const ui::Panel& panel, const ui::Widget* aim_at, double trigger) {
  hand.tracked = true;
  hand.aim = {position, rest};
  if (aim_at) {
    const glm::dvec3 d = glm::normalize(panel.world_of_pixel(aim_at->rect().centre()) - position);
    const Direction dir = effects::from_unit(Eigen::Vector3d(d.x, d.y, d.z));
    hand.aim.orientation = xr::look_rotation(dir.azimuth_deg, dir.altitude_deg);
  }
  hand.grip = hand.aim;
  hand.trigger = trigger;
}

TEST(EditorTrackPanel, TheHeadsetsLeftTriggerPressesTheSameButtonsOnTheTimelinePanel) {
  Editor ed(clip_sidecar(), DocumentOptions{{.async = false}}, on_clip(false));
  xr::ActionSync sync;
  std::int64_t t = 0;
  const auto frame = [&](const ui::Button* aim_at, double trigger) {
    xr::InputState in = test::looking(0.0, 0.0, ++t);
    aim_hand(in.left, {-0.2, 1.3, -0.1}, xr::look_rotation(-40.0, -30.0),
             *ed.panel(kTimelinePanelId), aim_at, trigger);
    ed.update(sync.sync(in), t);
  };
  frame(nullptr, 0.0);  // the panels find their places
  const ui::Button& b = ed.ui().track_section().subject_button();
  frame(&b, 0.0);
  frame(&b, 1.0);
  frame(&b, 0.0);
  ASSERT_NE(ed.document().track("subject1"), nullptr) << ed.hud_message();
  EXPECT_EQ(ed.document().undo_stack().undo_size(), 1u);
}

TEST(EditorTrackPanel, TheHeadsetsKeyboardStaysWhereItOpenedAndEitherRayTypesOnIt) {
  Editor ed(clip_sidecar(), DocumentOptions{{.async = false}}, on_clip(false));
  xr::ActionSync sync;
  std::int64_t t = 0;
  // A frame with the head looking at azimuth `head_az` and the right hand's ray on `aim_at`.
  const auto frame = [&](double head_az, const ui::Widget* aim_at, double trigger) {
    xr::InputState in = test::looking(head_az, 0.0, ++t);
    aim_hand(in.right, {0.2, 1.3, -0.1}, xr::look_rotation(0.0, -30.0), *ed.panel(kRenamePanelId),
             aim_at, trigger);
    ed.update(sync.sync(in), t);
  };
  const auto press = [&](double head_az, const ui::Widget& w) {
    frame(head_az, &w, 0.0);
    frame(head_az, &w, 1.0);
    frame(head_az, &w, 0.0);
  };
  frame(0.0, nullptr, 0.0);
  ed.track_subject();
  ASSERT_TRUE(ed.wait_for_tracking(std::chrono::seconds(60)));
  frame(0.0, nullptr, 0.0);
  ASSERT_NE(ed.document().track("subject1"), nullptr) << ed.hud_message();
  const RenameKeyboard& keys = ed.ui().rename_keyboard();
  ed.begin_rename();
  frame(0.0, nullptr, 0.0);
  frame(0.0, nullptr, 0.0);
  ASSERT_TRUE(keys.panel().visible());
  const glm::dvec3 opened = keys.panel().pose().position;
  EXPECT_LT(opened.z, -0.4);  // ahead of the head, which looks down -z
  frame(50.0, nullptr, 0.0);  // the head turns: the keyboard stays in the world
  EXPECT_LT(glm::length(keys.panel().pose().position - opened), 1e-9);
  press(50.0, *keys.key("x"));
  EXPECT_EQ(ed.track_view().rename.text, "subject1x");
  press(50.0, keys.cancel_button());
  EXPECT_FALSE(keys.panel().visible());
  ed.begin_rename();  // opened again while the head looks 50 degrees to the right
  frame(50.0, nullptr, 0.0);
  frame(50.0, nullptr, 0.0);
  EXPECT_GT(glm::length(keys.panel().pose().position - opened), 0.3);
  EXPECT_EQ(ed.document().track("subject1")->name, "subject1");  // cancelled: unchanged
}

}  // namespace
}  // namespace vdfx::app
