#include "featloc/pipeline/StepAssembler.h"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "featloc/core/InputError.h"
#include "featloc/math/DiagonalPoseGaussian.h"
#include "featloc/pipeline/BearingRangeHandler.h"
#include "featloc/pipeline/LaserScanHandler.h"
#include "featloc/pipeline/OdometryReadingHandler.h"

namespace featloc
{
namespace
{
/** [s] An action stamped this close to its scan was read with it. */
constexpr double kSameInstant = 1e-3;

std::string timeText(mrpt::Clock::time_point t)
{
	std::ostringstream ss;
	ss.setf(std::ios::fixed);
	ss.precision(6);
	ss << mrpt::Clock::toDouble(t);
	return ss.str();
}

double seconds(mrpt::Clock::time_point a, mrpt::Clock::time_point b)
{
	return std::chrono::duration<double>(b - a).count();
}
}  // namespace

StepAssembler::StepAssembler(
	const InputOptions& input, const OdometryOptions& odometry, std::string sourceName)
	: m_input(input), m_odo(odometry), m_sourceName(std::move(sourceName))
{
	auto laser = std::make_unique<LaserScanHandler>(
		LaserScanSelector(m_sourceName, input.laser_label, input.invalid_range_policy));
	auto bearingRange = std::make_unique<BearingRangeHandler>();
	m_laser = laser.get();
	m_bearingRange = bearingRange.get();
	addHandler(std::move(laser));
	addHandler(std::move(bearingRange));
	addHandler(std::make_unique<OdometryReadingHandler>());
}

StepAssembler::~StepAssembler() = default;

void StepAssembler::addHandler(ObservationHandler::Ptr handler)
{
	m_handlers.push_back(std::move(handler));
}

const LaserScanSelector& StepAssembler::selector() const { return m_laser->selector(); }

size_t StepAssembler::landmarkObservations() const { return m_bearingRange->observations(); }

bool StepAssembler::full() const
{
	return m_input.max_scans > 0 && m_nextScanIndex >= m_input.max_scans;
}

void StepAssembler::push(
	const RawlogEntry& entry, std::vector<StepSource>& used, std::vector<EstimationStep>& ready)
{
	using namespace mrpt::obs;
	if (auto actions = std::dynamic_pointer_cast<CActionCollection>(entry.object))
	{
		closeFrame();  // the motion to the next frame begins
		for (size_t i = 0; i < actions->size(); i++) onAction(actions->get(i));
	}
	else if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(entry.object))
	{
		// A sensory frame is one robot pose (MRPT's meaning): one step,
		// unless the log gives odometry readings to interpolate at each
		// observation's own time.
		bool readings = m_odometryReadings > 0;
		for (const auto& o : *sf) readings = readings || IS_CLASS(*o, CObservationOdometry);
		const bool wholeFrame = !readings;
		if (wholeFrame) closeFrame();
		std::vector<CObservation::Ptr> obs(sf->begin(), sf->end());
		std::stable_sort(
			obs.begin(), obs.end(), [](const CObservation::Ptr& a, const CObservation::Ptr& b) {
				return a->timestamp < b->timestamp;
			});
		for (const auto& o : obs) onObservation(o, entry.index, wholeFrame, used);
		if (wholeFrame) closeFrame();
	}
	else if (auto o = std::dynamic_pointer_cast<CObservation>(entry.object))
	{
		onObservation(o, entry.index, false, used);
		// A scan that can go without another reading (extrapolated odometry,
		// or no odometry at all so far) goes now: what could still join its
		// frame (another sensor at the very same time) is rare, and a live
		// pose would wait for the next entry.
		if (m_open && m_open->step.scan && needsNoLaterReading(m_open->step.time)) closeFrame();
	}
	else if (entry.object)
	{
		const std::string cls = entry.object->GetRuntimeClass()->className;
		m_perClass[cls]++;
		m_ignored[cls]++;
	}
	release(false, ready);
}

void StepAssembler::finish(std::vector<EstimationStep>& ready)
{
	closeFrame();
	release(true, ready);
}

void StepAssembler::onAction(const mrpt::serialization::CSerializable::Ptr& action)
{
	const std::string cls = action->GetRuntimeClass()->className;
	m_perClass[cls]++;
	auto move = std::dynamic_pointer_cast<mrpt::obs::CActionRobotMovement2D>(action);
	if (!move || !move->poseChange)
	{
		m_ignored[cls]++;
		return;
	}
	mrpt::poses::CPose2D mean;
	mrpt::math::CMatrixDouble33 cov;
	move->poseChange->getCovarianceAndMean(cov, mean);
	const mrpt::poses::CPosePDFGaussian inc = m_odo.covariance_source == "model"
		? m_odo.model.incrementPdf(mean)
		: mrpt::poses::CPosePDFGaussian(mean, cov);
	if (m_haveActions)
		m_actionSum += inc;	 // SE(2) composition with covariance propagation
	else
		m_actionSum = inc;
	m_haveActions = true;
	// MRPT's simulated log leaves actions unstamped (zero).
	m_lastActionTime.reset();
	if (move->timestamp != mrpt::Clock::time_point()) m_lastActionTime = move->timestamp;
	m_actions++;
}

void StepAssembler::onObservation(
	const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex, bool sameFrame,
	std::vector<StepSource>& used)
{
	const std::string cls = obs->GetRuntimeClass()->className;
	m_perClass[cls]++;
	ObservationHandler* handler = nullptr;
	for (const auto& h : m_handlers)
		if (obs->GetRuntimeClass()->derivedFrom(h->observationClass()))
		{
			handler = h.get();
			break;
		}
	if (!handler)
	{
		m_ignored[cls]++;
		return;
	}
	const std::string where =
		"rawlog '" + m_sourceName + "': entry #" + std::to_string(entryIndex);
	ObservationContribution c;
	if (!handler->handle(obs, entryIndex, where, c)) return;
	if (c.odometryReading)
	{
		onOdometryReading(obs->timestamp, *c.odometryReading, where);
		return;
	}

	const auto t = c.scan ? c.scan->timestamp : obs->timestamp;
	if (c.scan) checkScanTime(t, entryIndex, where);
	const bool join = m_open && !(c.scan && m_open->step.scan) &&
		(sameFrame || m_open->step.time == t);
	if (!join)
	{
		if (full()) return;
		closeFrame();
		openFrame(t, entryIndex, where);
	}
	EstimationStep& s = m_open->step;
	if (c.scan)
	{
		s.scan = c.scan;
		s.scanIndex = m_nextScanIndex++;
		s.source = obs.get();
		s.entryIndex = entryIndex;
		s.time = t;
	}
	else if (!s.source)
		s.source = obs.get();  // the outputs attach the pose after it
	s.landmarks.insert(s.landmarks.end(), c.landmarks.begin(), c.landmarks.end());
	if (c.stereo)
	{
		s.stereo = c.stereo;
		s.stereoImages = c.stereoImages;
	}
	used.push_back({s.index, obs.get()});
}

void StepAssembler::checkScanTime(
	mrpt::Clock::time_point t, size_t entryIndex, const std::string& where)
{
	if (m_lastScanTime && t <= *m_lastScanTime)
	{
		std::string msg = where + ": scan time " + timeText(t) +
			(t == *m_lastScanTime ? " repeats" : " is before") + " the previous scan's (" +
			timeText(*m_lastScanTime) + ", entry #" + std::to_string(m_lastScanEntry) +
			"); featloc needs strictly increasing scan times";
		if (t == *m_lastScanTime)
			msg +=
				" (MRPT 2.5.8's carmen2rawlog gives every observation the same time: convert "
				"CARMEN logs with correct timestamps)";
		throw InputError(msg);
	}
	m_lastScanTime = t;
	m_lastScanEntry = entryIndex;
}

void StepAssembler::onOdometryReading(
	mrpt::Clock::time_point t, const mrpt::poses::CPose2D& pose, const std::string& where)
{
	if (m_lastOdometryTime && t <= *m_lastOdometryTime)
	{
		if (t == *m_lastOdometryTime) return;  // duplicate
		throw InputError(
			where + ": odometry time " + timeText(t) +
			" is before the previous odometry reading's (" + timeText(*m_lastOdometryTime) +
			"); featloc needs the log in time order (rawlog-edit can sort it)");
	}
	m_lastOdometryTime = t;
	m_timeline.add(t, pose);
	m_odometryReadings++;
	// Nothing seen at the open frame's time can come after a later reading.
	if (m_open && t > m_open->step.time) closeFrame();
}

void StepAssembler::openFrame(mrpt::Clock::time_point t, size_t entryIndex, const std::string& where)
{
	if (m_lastStepTime && t < *m_lastStepTime)
		throw InputError(
			where + ": observation time " + timeText(t) + " is before the previous step's (" +
			timeText(*m_lastStepTime) + ", entry #" + std::to_string(m_lastStepEntry) +
			"); featloc needs the log in time order (rawlog-edit can sort it)");
	Pending p;
	p.step.index = m_nextStepIndex++;
	p.step.time = t;
	p.step.entryIndex = entryIndex;
	if (m_haveActions)
	{
		p.fromActions = true;
		p.step.hasOdometry = true;
		p.step.odometryFromActions = true;
		p.step.odometry = m_actionSum;
		p.actionTime = m_lastActionTime;
		m_haveActions = false;
	}
	m_lastStepTime = t;
	m_lastStepEntry = entryIndex;
	m_open = std::move(p);
}

void StepAssembler::closeFrame()
{
	if (!m_open) return;
	// A scan that joined later may have moved the frame's time forward.
	if (!m_lastStepTime || *m_lastStepTime < m_open->step.time)
		m_lastStepTime = m_open->step.time;
	// Stamped with the frame's own time: read at the scan's instant.
	if (m_open->actionTime)
		m_open->step.odometryReadAtScan =
			std::abs(mrpt::Clock::toDouble(*m_open->actionTime) -
				mrpt::Clock::toDouble(m_open->step.time)) <= kSameInstant;
	m_pending.push_back(std::move(*m_open));
	m_open.reset();
}

void StepAssembler::release(bool endOfLog, std::vector<EstimationStep>& ready)
{
	while (!m_pending.empty())
	{
		Pending& p = m_pending.front();
		const auto t = p.step.time;
		const bool odometryStopped =
			m_lastStepTime && seconds(t, *m_lastStepTime) > m_odo.max_interpolation_gap;
		if (!(endOfLog || p.fromActions || m_timeline.covers(t) || odometryStopped ||
				needsNoLaterReading(t)))
			break;	// wait for an odometry reading at or after t

		completeFromTimeline(p.step);
		if (p.step.index == 0)
		{
			p.step.hasOdometry = false;
			p.step.odometry = mrpt::poses::CPosePDFGaussian();
		}
		else if (!p.step.hasOdometry)
		{
			p.step.odometry = noOdometryPrior();
			m_stepsWithoutOdometry++;
		}
		m_timeline.forgetBefore(t);
		ready.push_back(std::move(p.step));
		m_pending.pop_front();
	}
}

bool StepAssembler::needsNoLaterReading(mrpt::Clock::time_point t) const
{
	// No reading yet: a source without odometry (a live run with only a
	// laser) must not hold every step max_interpolation_gap.
	return m_odometryReadings == 0 ||
		m_timeline.extrapolatedAt(t, m_odo.max_interpolation_gap, m_odo.max_extrapolation);
}

void StepAssembler::completeFromTimeline(EstimationStep& step)
{
	// Past the newest reading (max_extrapolation), else interpolated.
	auto odo =
		m_timeline.extrapolatedAt(step.time, m_odo.max_interpolation_gap, m_odo.max_extrapolation);
	if (odo)
		m_stepsExtrapolated++;
	else
		odo = m_timeline.poseAt(step.time, m_odo.max_interpolation_gap);
	if (!step.hasOdometry && odo && m_prevStepOdometry)
	{
		step.odometry = m_odo.model.incrementPdf(*odo - *m_prevStepOdometry);
		step.hasOdometry = true;
	}
	m_prevStepOdometry = odo;
}

mrpt::poses::CPosePDFGaussian StepAssembler::noOdometryPrior() const
{
	return diagonalPoseGaussian(
		mrpt::poses::CPose2D(), m_odo.no_odometry_sigma_xy, m_odo.no_odometry_sigma_yaw);
}
}  // namespace featloc
