/// @file
/// @brief A subject followed through a 360 video from one point (docs/anchors.md, "Subject
/// tracks"). Every frame is looked at through a small pinhole view centred on where the subject is
/// expected (effects::sample_view with the footprint filter), never on the equirect itself, so
/// the seam and the poles are no different from anywhere else:
///  - the template is the view of the subject at the start (`size_deg` wide over template_px
///    pixels);
///  - in each next frame, a view `search` subject widths wide is centred on the prediction (the
///    last direction moved on by the last frame's motion), its axes carried along by the
///    shortest-arc rotation between the centres (parallel transport: no spin near a pole), at the
///    subject's last size; the template, resized to that size and a scale_step either way (the
///    subject growing or shrinking), is found in it by normalised cross-correlation (OpenCV's
///    matchTemplate, TM_CCOEFF_NORMED) with a sub-pixel peak;
///  - a subject's look changes (it turns round, its light changes): each frame it is seen, a
///    second template is cut from that frame where it was found (at its size there). The start's
///    template is tried first and decides wherever it matches (it cannot drift); where it does not,
///    the renewed one is tried, with a higher bar (renew_score: a template renewed from a poor
///    match would slide onto the background). Matthews, Ishikawa and Baker ("The template update
///    problem", 2004) keep the first template against drift the same way;
///  - a peak below lost_score (with either template) means the subject is not seen (hidden, gone,
///    or changed beyond recognition): the last confident direction is held and searched around in
///    a view twice as wide, with the templates two and four steps either way too, until a peak of
///    found_score picks it up again.
/// Confidence is the peak's correlation where the subject is seen, 0 where it is held.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "effects/equirect_sampler.h"
#include "effects/view_camera.h"

namespace vdfx::app::track {

struct SubjectOptions {
  double size_deg = 10.0;    //!< the subject's width at the start frame
  int template_px = 32;      //!< the template's side, pixels
  double search = 3.0;       //!< the search view's side, in subject widths
  double lost_score = 0.6;   //!< correlation below: not seen
  double found_score = 0.7;  //!< correlation needed to pick a lost subject up again
  double renew_score = 0.8;  //!< correlation the renewed template needs where the start's fails
  double scale_step = 1.05;  //!< the sizes tried each frame: 1/step, 1, step times the last
  int coverage_deg = 360;    //!< of the frames' images: 360, or 180 (VR180)
};

struct SubjectSample {
  Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ();  //!< unit, the video frame's
  double confidence = 0.0;  //!< the correlation where seen; 0 where held
  double size_deg = 0.0;    //!< its width as it looks there
  bool seen = false;
};

class SubjectTracker {
 public:
  /// Takes the template from `equirect` (RGB CV_32FC3, the frame the track starts at) around
  /// `at`.
  SubjectTracker(const cv::Mat& equirect, const Eigen::Vector3d& at, const SubjectOptions& options);

  /// The subject in the next frame fed (forwards or backwards from the start frame).
  SubjectSample step(const cv::Mat& equirect);
  /// The start frame's sample (the given direction, confidence 1).
  SubjectSample start() const;

  /// The analysis equirect width (pixels per turn) at which a view's pixels and the equirect's
  /// are about the same size on the equator: what frames should be reduced to.
  static int equirect_width(const SubjectOptions& options);

 private:
  struct Match {
    double score = -1.0;
    Eigen::Vector3d direction;
    double scale = 1.0;
  };
  struct SearchView {
    effects::ViewCamera camera;
    cv::Mat view;
  };
  /// The view searched: `side_widths` subject widths wide at the last size, centred on the
  /// prediction.
  SearchView search_view(const effects::EquirectSampler& sampler, double side_widths) const;
  /// The best match of `templates` (one of templates_, renewed_) in the view.
  Match search(const SearchView& v, const std::vector<cv::Mat>& templates) const;
  /// A template at every size tried from `view` (template_px square).
  std::vector<cv::Mat> sizes_of(const cv::Mat& view) const;
  /// The renewed template: the view of the last confident direction at the subject's last size.
  void renew(const effects::EquirectSampler& sampler);

  SubjectOptions o_;
  double focal_ = 0.0;              //!< template pixels per radian at scale 1
  std::vector<cv::Mat> templates_;  //!< the start's view resized by scale_step^-4 .. ^4
  std::vector<cv::Mat> renewed_;    //!< the same from the last frame the subject was seen in
  Eigen::Matrix3d axes_;            //!< the view's camera-to-world, centred on the last direction
  Eigen::Vector3d last_;            //!< the last confident direction
  Eigen::Quaterniond velocity_ = Eigen::Quaterniond::Identity();  //!< last frame's motion
  double scale_ = 1.0;
  bool lost_ = false;
};

}  // namespace vdfx::app::track
