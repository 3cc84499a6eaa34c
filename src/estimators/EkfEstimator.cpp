#include "featloc/estimators/EkfEstimator.h"

#include <mrpt/obs/CObservationStereoImages.h>

#include <Eigen/Core>
#include <cmath>

#include "featloc/estimators/StereoStepResult.h"
#include "featloc/io/DecodedStereoPair.h"
#include "featloc/stereo/StereoLandmarkExtractor.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(EkfEstimator, PoseEstimator, featloc)

namespace
{
/** [m^2 or rad^2] What a match's direction taken from the guess adds to
 * its covariance before fusion: no information there. */
constexpr double kFreeDirectionVariance = 1e4;
}  // namespace

void EkfEstimator::loadParams(const mrpt::config::CConfigFileBase& cfg)
{
	m_filter.options.loadFromConfigFile(cfg, paramsSection());
}

void EkfEstimator::saveParams(mrpt::config::CConfigFileBase& cfg) const
{
	m_filter.options.saveToConfigFile(cfg, paramsSection());
}

void EkfEstimator::initialize(const mrpt::poses::CPosePDFGaussian& initialPose)
{
	m_filter.reset(initialPose);
	m_pose = m_filter.robotPose();
	m_reason.clear();
	m_lastStereo.reset();
}

bool EkfEstimator::process(const EstimationStep& step, const MatchResult* match)
{
	m_filter.predict(step.odometry, step.odometrySamplingCovariance);
	m_reason.clear();
	bool used = false;
	if (match && match->success)
	{
		mrpt::poses::CPosePDFGaussian z = match->estimate;
		z.cov *= m_filter.options.matcher_covariance_scale;
		if (match->guessKeptAlongFreeDirection)
		{
			// Along the direction the scans left free the match is the
			// guess, which is this filter's own odometry: fused again it
			// would count twice. The filter keeps its prediction there.
			const Eigen::Vector3d w = match->freeDirection.asEigen();
			z.cov += mrpt::math::CMatrixDouble33(Eigen::Matrix3d(kFreeDirectionVariance * w * w.transpose()));
		}
		// Gated against the state without this keyframe's earlier matches:
		// they measured (nearly) the same thing, with (nearly) the same
		// error, so only the latest accepted one is held for fusion.
		// No gate allowance: the state holds the odometry's sampling error
		// (EkfLocalizer::predict), which is what the allowance stands for.
		// A match whose guess-gate rejection the scans overruled has been
		// tested against the odometry already, by evidence the gate has not
		// got (ScanMatcher::arbitrateGuessGate): the EKF's gate, whose
		// prediction is that odometry, is not asked again. Growing the
		// robot's covariance by the disagreement first was measured worse
		// (doc/benchmarks.md, "Overruled guess-gate rejections").
		const bool overruled = !match->guessGateOverruled.empty();
		const auto u = overruled ? EkfLocalizer::MotionUpdate{true, 0.0, ""}
								 : m_filter.testRelativeMotion(z);
		used = u.used;
		m_reason = u.reason;
		if (used) m_filter.holdRelativeMotion(z);
	}
	else if (match)
		m_reason = "the match failed: " + match->failureReason;
	if (!step.landmarks.empty()) m_filter.updateLandmarks(step.landmarks);
	m_lastStereo.reset();
	if (m_stereo && step.stereo && step.stereoImages) processStereo(step);
	m_pose = m_filter.robotPose();
	return used;
}

bool EkfEstimator::fuseAbsolutePose(
	const mrpt::poses::CPosePDFGaussian& z, double gateChi2, std::string& reason)
{
	const auto u = m_filter.updateAbsolutePose(z, gateChi2);
	reason = u.reason;
	m_pose = m_filter.robotPose();
	return u.used;
}

std::optional<std::pair<double, double>> EkfEstimator::odometryDirectionOffset() const
{
	if (!(m_filter.options.odometry_direction_sigma > 0)) return {};
	const auto D = EkfLocalizer::kOdometryDirection;
	return std::make_pair(m_filter.state()[D], std::sqrt(m_filter.covariance()(D, D)));
}

std::vector<EstimatedLandmark> EkfEstimator::landmarks() const
{
	auto out = m_filter.landmarks();
	if (m_stereo)
		for (auto& l : out)
			if (l.vertical) l.plane = m_stereo->planeName(l.wall);
	return out;
}

void EkfEstimator::processStereo(const EstimationStep& step)
{
	const std::string where = "entry #" + std::to_string(step.entryIndex) + " (stereo '" +
		step.stereo->sensorLabel + "')";
	const StereoHead head = StereoHead::fromObservation(*step.stereo, where);
	auto r = std::make_shared<StereoStepResult>();
	r->frame = m_stereo->process(
		step.stereoImages->left, step.stereoImages->right, head, m_filter.robotPose());
	r->update = m_filter.updateVerticalLandmarks(r->frame.observations, r->frame.walls);
	r->map = m_stereo->mapFile();
	m_lastStereo = std::move(r);
}

void EkfEstimator::markKeyframe()
{
	m_filter.cloneKeyframe();  // fuses the held match of the ending interval
	m_pose = m_filter.robotPose();
}
}  // namespace featloc
