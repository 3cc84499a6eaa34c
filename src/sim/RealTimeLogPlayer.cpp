#include "featloc/sim/RealTimeLogPlayer.h"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "featloc/core/InputError.h"
#include "featloc/io/RawlogFileSource.h"
#include "featloc/io/TumRow.h"
#include "featloc/sim/StereoCameraRecording.h"

namespace featloc
{
std::vector<RealTimeLogPlayer::Item> RealTimeLogPlayer::load(
	const std::string& rawlogPath, const std::vector<mrpt::poses::CPose2D>& truths)
{
	using namespace mrpt::obs;
	RawlogFileSource reader(rawlogPath);
	std::vector<Item> items;
	RawlogEntry entry;
	size_t scans = 0;
	auto absoluteImage = [&](mrpt::img::CImage& img) {
		if (!img.isExternallyStored()) return;
		std::filesystem::path file(img.getExternalStorageFile());
		if (file.is_relative()) file = std::filesystem::path(reader.imagesDirectory()) / file;
		img.setExternalStorage(std::filesystem::absolute(file).string());
	};
	while (reader.next(entry))
	{
		Item item;
		if (auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(entry.object))
		{
			if (scans >= truths.size())
				throw InputError(
					"rawlog '" + rawlogPath + "': more scans than true poses (" +
					std::to_string(truths.size()) + ")");
			item.isScan = true;
			item.t = mrpt::Clock::toDouble(scan->timestamp);
			item.truth = truths[scans++];
			item.ranges.resize(scan->getScanSize());
			for (size_t i = 0; i < item.ranges.size(); i++)
				item.ranges[i] = scan->getScanRangeValidity(i) ? scan->getScanRange(i) : 0.f;
		}
		else if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(entry.object))
		{
			item.t = mrpt::Clock::toDouble(odo->timestamp);
			item.odometry.time = item.t;
			item.odometry.pose = odo->odometry;
			item.odometry.hasVelocities = odo->hasVelocities;
			item.odometry.v = odo->velocityLocal.vx;
			item.odometry.w = odo->velocityLocal.omega;
		}
		else if (auto pair = std::dynamic_pointer_cast<CObservationStereoImages>(entry.object))
		{
			item.t = mrpt::Clock::toDouble(pair->timestamp);
			absoluteImage(pair->imageLeft);
			if (pair->hasImageRight) absoluteImage(pair->imageRight);
			item.stereo = pair;
		}
		else
			throw InputError(
				"rawlog '" + rawlogPath + "': entry #" + std::to_string(entry.index) +
				" is not a 2-D scan, an odometry reading or a stereo pair; the device "
				"emulator plays format-#2 logs of those");
		items.push_back(std::move(item));
	}
	if (scans != truths.size())
		throw InputError(
			"rawlog '" + rawlogPath + "': " + std::to_string(scans) + " scans for " +
			std::to_string(truths.size()) + " true poses");
	return items;
}

RealTimeLogPlayer::RealTimeLogPlayer(std::vector<EmulatedLaser*> lasers,
	OdometryLineServer* odometry, std::string groundTruthPath)
	: m_lasers(std::move(lasers)), m_odometry(odometry), m_gtPath(std::move(groundTruthPath))
{
}

RealTimeLogPlayer::Result RealTimeLogPlayer::play(
	const std::vector<Item>& items, const std::atomic<bool>* stop,
	const std::function<void(double)>& onProgress)
{
	Result r;
	auto stopped = [&] { return stop && stop->load(); };
	// The device starts when its driver asks for data (and the base when
	// its client is there), so the whole log reaches the drivers.
	auto allStream = [&] {
		for (const auto* l : m_lasers)
			if (!l->streaming()) return false;
		return true;
	};
	while (!stopped() && !(allStream() && (!m_odometry || m_odometry->clients() > 0)))
		std::this_thread::sleep_for(std::chrono::milliseconds(5));
	std::ofstream gt(m_gtPath);
	if (!gt) throw std::runtime_error("cannot write '" + m_gtPath + "'");
	gt << "# featloc-sim --serve ground truth (TUM format): t x y z qx qy qz qw of the robot "
		  "at every scan sent, t on this computer's clock\n";
	if (items.empty() || stopped())
	{
		r.stopped = stopped();
		return r;
	}
	const double tFirst = items.front().t;
	const double wall0 = mrpt::Clock::toDouble(mrpt::Clock::now());
	const auto steady0 = std::chrono::steady_clock::now();
	if (!m_cameraPath.empty())
	{
		std::vector<std::shared_ptr<mrpt::obs::CObservationStereoImages>> pairs;
		for (const Item& item : items)
			if (item.stereo) pairs.push_back(item.stereo);
		r.stereoPairs = StereoCameraRecording::write(m_cameraPath, pairs, tFirst, wall0);
	}
	size_t k = 0;
	std::vector<bool> begun(m_faults.size(), false), ended(m_faults.size(), false);
	for (const Item& item : items)
	{
		if (stopped())
		{
			r.stopped = true;
			break;
		}
		std::this_thread::sleep_until(
			steady0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
						  std::chrono::duration<double>(item.t - tFirst)));
		const double wallT = wall0 + (item.t - tFirst);
		if (item.isScan)
		{
			r.scans++;
			const double rel = item.t - tFirst;
			const auto deviceMs = static_cast<uint32_t>(rel * 1000.0 + 0.5);
			bool garbage = false;
			for (size_t f = 0; f < m_faults.size(); f++)
			{
				const DeviceFault& fault = m_faults[f];
				if (!begun[f] && rel >= fault.at)
				{
					begun[f] = true;
					r.faultsInjected++;
					for (auto* l : m_lasers)
						if (fault.kind == DeviceFault::Kind::Outage)
							l->setReachable(false);
						else if (fault.kind == DeviceFault::Kind::Stall)
							l->setSilent(true);
					garbage = garbage || fault.kind == DeviceFault::Kind::Garbage;
				}
				if (begun[f] && !ended[f] && fault.kind != DeviceFault::Kind::Garbage &&
					rel >= fault.at + fault.duration)
				{
					ended[f] = true;
					for (auto* l : m_lasers)
						if (fault.kind == DeviceFault::Kind::Outage)
							l->setReachable(true);
						else
							l->setSilent(false);
				}
			}
			for (auto* l : m_lasers)
				if (garbage)
					l->publishGarbage(deviceMs);
				else
					l->publish(item.ranges, deviceMs);
			gt << tumRow(wallT, item.truth) << std::flush;
		}
		else if (!item.stereo)
		{
			r.readings++;
			OdometryLine line = item.odometry;
			line.time = wallT;
			if (m_odometry && m_odometry->publish(line) > 0) r.readingsDelivered++;
		}
		if (onProgress && (++k % 64 == 0)) onProgress(static_cast<double>(k) / items.size());
	}
	r.seconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - steady0).count();
	return r;
}
}  // namespace featloc
