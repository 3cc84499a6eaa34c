#include "featloc/pipeline/ScanStepAssembler.h"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "featloc/core/InputError.h"
#include "featloc/math/DiagonalPoseGaussian.h"

namespace featloc
{
namespace
{
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

ScanStepAssembler::ScanStepAssembler(
	const InputOptions& input, const OdometryOptions& odometry,
	std::string rawlogName)
	: m_input(input),
	  m_odo(odometry),
	  m_rawlogName(std::move(rawlogName)),
	  m_selector(m_rawlogName, input.laser_label, input.invalid_range_policy)
{
}

bool ScanStepAssembler::full() const
{
	return m_input.max_scans > 0 && m_nextScanIndex >= m_input.max_scans;
}

void ScanStepAssembler::push(
	const RawlogEntry& entry, std::vector<SelectedScan>& selected,
	std::vector<ScanStep>& ready)
{
	using namespace mrpt::obs;
	if (auto actions = std::dynamic_pointer_cast<CActionCollection>(entry.object))
	{
		for (size_t i = 0; i < actions->size(); i++) onAction(actions->get(i));
	}
	else if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(entry.object))
	{
		std::vector<CObservation::Ptr> obs(sf->begin(), sf->end());
		std::stable_sort(
			obs.begin(), obs.end(),
			[](const CObservation::Ptr& a, const CObservation::Ptr& b) {
				return a->timestamp < b->timestamp;
			});
		for (const auto& o : obs) onObservation(o, entry.index, selected);
	}
	else if (auto o = std::dynamic_pointer_cast<CObservation>(entry.object))
	{
		onObservation(o, entry.index, selected);
	}
	release(false, ready);
}

void ScanStepAssembler::finish(std::vector<ScanStep>& ready)
{
	release(true, ready);
}

void ScanStepAssembler::onAction(
	const mrpt::serialization::CSerializable::Ptr& action)
{
	auto move =
		std::dynamic_pointer_cast<mrpt::obs::CActionRobotMovement2D>(action);
	if (!move || !move->poseChange) return;
	mrpt::poses::CPose2D mean;
	mrpt::math::CMatrixDouble33 cov;
	move->poseChange->getCovarianceAndMean(cov, mean);
	const mrpt::poses::CPosePDFGaussian inc = m_odo.covariance_source == "model"
		? modelIncrement(mean)
		: mrpt::poses::CPosePDFGaussian(mean, cov);
	if (m_haveActions)
		m_actionSum += inc;	 // SE(2) composition with covariance propagation
	else
		m_actionSum = inc;
	m_haveActions = true;
	m_actions++;
}

void ScanStepAssembler::onObservation(
	const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex,
	std::vector<SelectedScan>& selected)
{
	const std::string where =
		"rawlog '" + m_rawlogName + "': entry #" + std::to_string(entryIndex);

	if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs))
	{
		if (odo->timestamp == INVALID_TIMESTAMP)
			throw InputError(
				where + ": odometry observation '" + odo->sensorLabel +
				"' has no valid timestamp");
		if (m_lastOdometryTime && odo->timestamp <= *m_lastOdometryTime)
		{
			if (odo->timestamp == *m_lastOdometryTime) return;	// duplicate
			throw InputError(
				where + ": odometry time " + timeText(odo->timestamp) +
				" is before the previous odometry reading's (" +
				timeText(*m_lastOdometryTime) +
				"); featloc needs the log in time order (rawlog-edit can "
				"sort it)");
		}
		m_lastOdometryTime = odo->timestamp;
		m_timeline.add(odo->timestamp, odo->odometry);
		m_odometryReadings++;
		return;
	}

	if (auto br = std::dynamic_pointer_cast<mrpt::obs::CObservationBearingRange>(obs))
	{
		addLandmarks(*br, where);
		return;
	}

	if (full()) return;
	auto scan = m_selector.select(obs, entryIndex);
	if (!scan) return;

	if (m_lastScanTime && scan->timestamp <= *m_lastScanTime)
	{
		std::string msg = where + ": scan time " + timeText(scan->timestamp) +
			(scan->timestamp == *m_lastScanTime ? " repeats" : " is before") +
			" the previous scan's (" + timeText(*m_lastScanTime) +
			", entry #" + std::to_string(m_lastScanEntry) +
			"); featloc needs strictly increasing scan times";
		if (scan->timestamp == *m_lastScanTime)
			msg +=
				" (MRPT 2.5.8's carmen2rawlog gives every observation the "
				"same time: convert CARMEN logs with correct timestamps)";
		throw InputError(msg);
	}
	m_lastScanTime = scan->timestamp;
	m_lastScanEntry = entryIndex;

	Pending p;
	p.step.scanIndex = m_nextScanIndex++;
	p.step.entryIndex = entryIndex;
	p.step.scan = scan;
	p.step.source = obs.get();
	if (m_haveActions)
	{
		p.fromActions = true;
		p.step.hasOdometry = true;
		p.step.odometry = m_actionSum;
		m_haveActions = false;
	}
	p.step.landmarks = std::move(m_landmarks);
	m_landmarks.clear();
	selected.push_back({p.step.scanIndex, p.step.source});
	m_pending.push_back(std::move(p));
}

void ScanStepAssembler::addLandmarks(
	const mrpt::obs::CObservationBearingRange& obs, const std::string& where)
{
	if (obs.timestamp == INVALID_TIMESTAMP)
		throw InputError(
			where + ": range-bearing observation '" + obs.sensorLabel +
			"' has no valid timestamp");
	for (size_t i = 0; i < obs.sensedData.size(); i++)
	{
		const auto& m = obs.sensedData[i];
		const bool finite = std::isfinite(m.range) && std::isfinite(m.yaw) &&
			(!obs.validCovariances || m.covariance.array().isFinite().all());
		if (!finite || m.range < 0)
			throw InputError(
				where + ": range-bearing observation '" + obs.sensorLabel +
				"': landmark #" + std::to_string(i) +
				" has a negative or non-finite range, bearing or covariance");
	}
	const auto obsList = LandmarkObservation::fromBearingRange(obs);
	for (size_t i = 0; i < obsList.size(); i++)
	{
		const auto& o = obsList[i];
		// A zero or indefinite covariance would make the filter claim
		// certainty it has not got.
		if (!(o.covariance.determinant() > 0 && o.covariance(0, 0) > 0))
			throw InputError(
				where + ": range-bearing observation '" + obs.sensorLabel +
				"': landmark #" + std::to_string(i) +
				" has no positive-definite covariance (set sensor_std_range "
				"and sensor_std_yaw, or per-landmark covariances)");
	}
	m_landmarks.insert(m_landmarks.end(), obsList.begin(), obsList.end());
	m_landmarkObservations++;
}

void ScanStepAssembler::release(bool endOfLog, std::vector<ScanStep>& ready)
{
	while (!m_pending.empty())
	{
		Pending& p = m_pending.front();
		const auto t = p.step.timestamp();
		const bool odometryStopped = m_lastScanTime &&
			seconds(t, *m_lastScanTime) > m_odo.max_interpolation_gap;
		if (!(endOfLog || p.fromActions || m_timeline.covers(t) ||
			  odometryStopped))
			break;	// wait for an odometry reading at or after t

		completeFromTimeline(p.step);
		if (p.step.scanIndex == 0)
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

void ScanStepAssembler::completeFromTimeline(ScanStep& step)
{
	const auto odo =
		m_timeline.poseAt(step.timestamp(), m_odo.max_interpolation_gap);
	if (!step.hasOdometry && odo && m_prevScanOdometry)
	{
		step.odometry = modelIncrement(*odo - *m_prevScanOdometry);
		step.hasOdometry = true;
	}
	m_prevScanOdometry = odo;
}

mrpt::poses::CPosePDFGaussian ScanStepAssembler::noOdometryPrior() const
{
	return diagonalPoseGaussian(
		mrpt::poses::CPose2D(), m_odo.no_odometry_sigma_xy, m_odo.no_odometry_sigma_yaw);
}

mrpt::poses::CPosePDFGaussian ScanStepAssembler::modelIncrement(
	const mrpt::poses::CPose2D& increment) const
{
	return m_odo.model.incrementPdf(increment);
}

}  // namespace featloc
