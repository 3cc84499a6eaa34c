// featloc-live against featloc-sim's device emulator over loopback: MRPT's
// own CHokuyoURG driver and featloc's TcpOdometrySensor, real sockets,
// real processes; and the emulator's protocol checked with the driver
// in-process.
#include <gtest/gtest.h>
#include <mrpt/hwdrivers/CHokuyoURG.h>
#include <mrpt/hwdrivers/CLMS100eth.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "featloc/core/InputError.h"
#include "featloc/io/OdometryLine.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/live/DriverQuirks.h"
#include "featloc/live/LiveOptions.h"
#include "featloc/sim/DeviceFault.h"
#include "featloc/sim/ScipLaserServer.h"
#include "featloc/sim/SickLaserServer.h"
#include "support/LiveEmulator.h"
#include "support/CommandRunner.h"
#include "support/DataRows.h"
#include "support/JsonFile.h"
#include "support/FreePort.h"
#include "support/DocumentedKeys.h"
#include "support/TempDir.h"
#include "support/TextFile.h"

using namespace featloc;
using namespace featloc::test;
namespace fs = std::filesystem;

namespace
{
const std::string kLive = FEATLOC_LIVE_EXE;
const std::string kRun = FEATLOC_RUN_EXE;
const std::string kSim = FEATLOC_SIM_EXE;
const std::string kConfig = std::string(FEATLOC_SOURCE_DIR) + "/configs/live-emulator.ini";
const std::string kWorld = std::string(FEATLOC_SOURCE_DIR) + "/worlds/office.ini";

struct Recorded
{
	size_t scans = 0, odometry = 0;
};
Recorded countRecorded(const std::string& rawlog)
{
	RawlogReader reader(rawlog);
	RawlogEntry e;
	Recorded r;
	while (reader.next(e))
	{
		r.scans += IS_CLASS(*e.object, mrpt::obs::CObservation2DRangeScan);
		r.odometry += IS_CLASS(*e.object, mrpt::obs::CObservationOdometry);
	}
	return r;
}
/** What the emulator says it delivered (its last line): the scans the
 * driver kept and the odometry readings. CHokuyoURG re-runs its handshake
 * inside initialize() and skips what the device sent before the QT echo:
 * those scans never reach featloc-live. */
struct Delivered
{
	size_t scans = 0, odometry = 0;
};
Delivered emulatorDelivered(const std::string& emulatorOutput)
{
	std::smatch odo, laser;
	if (!std::regex_search(emulatorOutput, odo,
			std::regex("(\\d+) of \\d+ odometry readings delivered")) ||
		!std::regex_search(emulatorOutput, laser,
			std::regex("Hokuyo: (\\d+) of them delivered \\((\\d+) skipped by the driver while "
					   "it re-initialised the device\\)")))
		throw std::runtime_error("no delivery lines in:\n" + emulatorOutput);
	return {std::stoul(laser[1]) - std::stoul(laser[2]), std::stoul(odo[1])};
}

}  // namespace

TEST(OdometryLine, FormatsAndParsesTheDocumentedLines)
{
	OdometryLine a;
	a.time = 1700000000.25;
	a.pose = mrpt::poses::CPose2D(1.5, -2.25, 0.5);
	const auto b = OdometryLine::parse(a.format());
	ASSERT_TRUE(b);
	EXPECT_DOUBLE_EQ(b->time, a.time);
	EXPECT_NEAR(b->pose.x(), 1.5, 1e-9);
	EXPECT_NEAR(b->pose.phi(), 0.5, 1e-8);
	EXPECT_FALSE(b->hasVelocities);
	const auto v = OdometryLine::parse("ODOM 3 1 2 0.1 0.5 -0.2\r\n");
	ASSERT_TRUE(v);
	EXPECT_TRUE(v->hasVelocities);
	EXPECT_DOUBLE_EQ(v->w, -0.2);
	EXPECT_FALSE(OdometryLine::parse("# a comment"));
	EXPECT_FALSE(OdometryLine::parse("   "));
	for (const char* bad : {"POSE 1 2 3 4", "ODOM 1 2 3", "ODOM 1 2 3 nan", "ODOM 1 2 3 4 5",
			 "ODOM 1 2 3x 4"})
	{
		try
		{
			OdometryLine::parse(bad);
			ADD_FAILURE() << "accepted '" << bad << "'";
		}
		catch (const InputError& e)
		{
			EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
		}
	}
}

TEST(ScipLaserServer, MrptsHokuyoDriverReadsTheScansSent)
{
	const unsigned short port = freePort();
	ScipLaserServer server(ScipLaserServer::deviceFor(1081, 1.5 * M_PI, 30.0, 40), port);
	mrpt::hwdrivers::CHokuyoURG driver;
	driver.setIPandPort("127.0.0.1", port);
	static_cast<mrpt::hwdrivers::CGenericSensor&>(driver).initialize();	 // SCIP 2.0 handshake, MD
	ASSERT_TRUE(server.streaming());

	std::vector<float> ranges(1081);
	for (size_t i = 0; i < ranges.size(); i++) ranges[i] = 0.5f + 0.01f * static_cast<float>(i);
	ranges[7] = 0;	// no return
	ranges[8] = std::numeric_limits<float>::infinity();
	mrpt::obs::CObservation2DRangeScan scan;
	bool got = false;
	for (int k = 0; k < 50 && !got; k++)
	{
		server.publish(ranges, static_cast<uint32_t>(25 * k));
		bool hwError = false;
		driver.doProcessSimple(got, scan, hwError);
		ASSERT_FALSE(hwError);
	}
	ASSERT_TRUE(got);
	ASSERT_EQ(scan.getScanSize(), 1081u);
	for (size_t i = 0; i < ranges.size(); i++)
	{
		if (i == 7 || i == 8)
			EXPECT_FALSE(scan.getScanRangeValidity(i)) << i;
		else
		{
			EXPECT_TRUE(scan.getScanRangeValidity(i)) << i;
			EXPECT_NEAR(scan.getScanRange(i), ranges[i], 0.0006) << i;  // mm on the wire
		}
	}
	// MRPT 2.5.8 takes the aperture as beams x (2 pi / ARES): 270.25 deg
	// for the 270 deg of 1081 beams 0.25 deg apart (doc/live.md).
	EXPECT_NEAR(scan.aperture, 1081 * 2 * M_PI / 1440, 1e-5);
	EXPECT_EQ(server.connections(), 1u);
}

TEST(SickLaserServer, MrptsLms100DriverReadsTheScansSent)
{
	const unsigned short port = freePort();
	// What MRPT 2.5.8's CLMS100Eth asks for: 25 Hz, 0.25 deg over 270 deg.
	const auto device = SickLaserServer::deviceFor(1081, 1.5 * M_PI, 25);
	EXPECT_EQ(device.resolution, 2500);
	EXPECT_EQ(device.startAngle, -450000);
	EXPECT_EQ(device.stopAngle, 2250000);
	SickLaserServer server(device, port);
	mrpt::hwdrivers::CLMS100Eth driver("127.0.0.1", port);
	const auto t0 = std::chrono::steady_clock::now();
	driver.initialize();  // login, scan configuration, start, ready (~15 s)
	const double initSeconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	EXPECT_TRUE(server.configurationMismatch().empty()) << server.configurationMismatch();

	std::vector<float> ranges(1081);
	for (size_t i = 0; i < ranges.size(); i++) ranges[i] = 0.5f + 0.01f * static_cast<float>(i);
	ranges[7] = 0;	// no return
	mrpt::obs::CObservation2DRangeScan scan;
	bool got = false, hwError = false;
	server.publish(ranges, 40);
	driver.doProcessSimple(got, scan, hwError);
	ASSERT_TRUE(got);
	ASSERT_FALSE(hwError);
	EXPECT_TRUE(server.streaming());
	ASSERT_EQ(scan.getScanSize(), 1081u);
	for (size_t i = 0; i < ranges.size(); i++)
	{
		if (i != 7)
		{
			EXPECT_NEAR(scan.getScanRange(i), ranges[i], 0.0006) << i;	// mm on the wire
		}
	}
	// The device sends 0 for no return; MRPT 2.5.8 keeps it as a valid 0 m.
	EXPECT_EQ(scan.getScanRange(7), 0.0f);
	// MRPT 2.5.8 fixes the aperture at 270 deg and says the beams go left
	// to right; the LMS1xx turns counter-clockwise, from its right
	// (featloc-live corrects it: doc/live.md).
	EXPECT_NEAR(scan.aperture, 1.5 * M_PI, 1e-5);
	EXPECT_FALSE(scan.rightToLeft);
	// The same scan again when polled before the next one, as the device.
	driver.doProcessSimple(got, scan, hwError);
	EXPECT_TRUE(got);
	EXPECT_EQ(server.scansSent(), 1u);
	EXPECT_EQ(server.scansResent(), 1u);
	// A damaged telegram: the driver reports a hardware error.
	server.publishGarbage(80);
	driver.doProcessSimple(got, scan, hwError);
	EXPECT_FALSE(got);
	EXPECT_TRUE(hwError);
	EXPECT_GT(initSeconds, 10.0);  // the driver's own sleeps
	EXPECT_EQ(server.connections(), 1u);
}

TEST(DriverQuirks, ClmsScansTurnRightToLeftAndTheirZeroBeamsAreInvalid)
{
	auto scanAsClmsGivesIt = [] {
		mrpt::obs::CObservation2DRangeScan scan;
		scan.resizeScan(3);
		for (size_t i = 0; i < 3; i++)
		{
			scan.setScanRange(i, i == 1 ? 0.0f : 2.0f);
			scan.setScanRangeValidity(i, true);	 // CLMS100Eth: 0 <= maxRange
		}
		scan.rightToLeft = false;
		return scan;
	};
	auto clms = scanAsClmsGivesIt();
	DriverQuirks::correct("CLMS100Eth", clms);
	EXPECT_TRUE(clms.rightToLeft);
	EXPECT_TRUE(clms.getScanRangeValidity(0));
	EXPECT_FALSE(clms.getScanRangeValidity(1));
	EXPECT_TRUE(clms.getScanRangeValidity(2));
	EXPECT_FALSE(DriverQuirks::describe("CLMS100Eth").empty());
	// Other drivers' observations are left as they come.
	auto other = scanAsClmsGivesIt();
	DriverQuirks::correct("CHokuyoURG", other);
	EXPECT_FALSE(other.rightToLeft);
	EXPECT_TRUE(other.getScanRangeValidity(1));
	EXPECT_TRUE(DriverQuirks::describe("CHokuyoURG").empty());
}

TEST(Live, EmulatedHokuyoAndOdometryRunAndReplayToTheSamePoses)
{
	TempDir dir;
	const unsigned short laser = freePort(), odo = freePort();
	const std::string out = dir.file("live"), replay = dir.file("replay");
	const std::string prefix = dir.file("emu");
	const CommandResult r = runCommand(emulatorCommand(prefix, laser, odo) +
		shellQuote(kLive) + " " + liveArgs(laser, odo) + " --duration 4 --out " + shellQuote(out) +
		" --set Evaluation:ground_truth=" + shellQuote(prefix + ".served.gt.txt") +
		"; code=$?; kill -TERM $emu; wait $emu; echo exit=$code");
	ASSERT_NE(r.output.find("exit=0"), std::string::npos) << r.output;

	const auto s = readJson(out + "/summary.json");
	EXPECT_EQ(s["status"], "ok");
	EXPECT_EQ(s["live"]["stopped_by"], "--duration reached");
	const auto& lidar = s["live"]["sensors"][0];
	const auto& base = s["live"]["sensors"][1];
	EXPECT_EQ(lidar["driver"], "CHokuyoURG");
	// Under the sanitizers the emulator itself cannot keep its rates: there
	// the check is only that both sensors delivered steadily.
#ifdef FEATLOC_SANITIZED_BUILD
	const double tolerance = 0.8;
#else
	const double tolerance = 0.1;
#endif
	EXPECT_NEAR(lidar["rate_hz"].get<double>(), 40.0, 40.0 * tolerance);
	EXPECT_NEAR(base["rate_hz"].get<double>(), 100.0, 100.0 * tolerance);
	// A reading may come late when ctest's other tests load both cores (one
	// odometry reading in 402 was seen once, one scan in 162 another time):
	// at most 1% of them, and every reading is passed on or counted late.
	EXPECT_EQ(lidar["received"].get<size_t>(),
		lidar["passed_on"].get<size_t>() + lidar["late"].get<size_t>());
	EXPECT_EQ(base["received"].get<size_t>(),
		base["passed_on"].get<size_t>() + base["late"].get<size_t>());
	const size_t late = s["live"]["late_observations"].get<size_t>();
	EXPECT_LE(100 * late, lidar["received"].get<size_t>() + base["received"].get<size_t>()) << late << " late";
	// Against the emulator's truth: the office at 0.6 m/s, 4 s.
	EXPECT_LT(s["evaluation"]["ate_m"]["rmse"].get<double>(), 0.05) << s.dump(1);

	// Everything passed on is in live.rawlog, in order; a late reading in
	// live-late.rawlog.
	const Recorded rec = countRecorded(out + "/live.rawlog");
	const Recorded lateRec = countRecorded(out + "/live-late.rawlog");
	EXPECT_EQ(rec.scans + lateRec.scans, lidar["received"].get<size_t>());
	EXPECT_EQ(rec.odometry + lateRec.odometry, base["received"].get<size_t>());
	EXPECT_EQ(lateRec.scans + lateRec.odometry, late);
	EXPECT_EQ(s["counts"]["scans"].get<size_t>(), rec.scans);

	// featloc-run replays the recording, with the live config as it is, to
	// the same poses.
	const CommandResult rr = runCommand(shellQuote(kRun) + " " + shellQuote(kConfig) + " " +
		shellQuote(out + "/live.rawlog") + " -q --out " + shellQuote(replay));
	ASSERT_EQ(rr.exitCode, 0) << rr.output;
	const auto a = dataRows(out + "/trajectory.tum"), b = dataRows(replay + "/trajectory.tum");
	ASSERT_FALSE(a.empty());
	EXPECT_EQ(a, b);
}

TEST(Live, AHokuyoAndASickTogetherWithOdometryAreRecordedAndReplayed)
{
	TempDir dir;
	const unsigned short laser = freePort(), sick = freePort(), odo = freePort();
	const std::string out = dir.file("live"), replay = dir.file("replay");
	const std::string prefix = dir.file("emu");
	const std::string both = " --set \"Live:sensors=LASER SICK ODOMETRY\" --set SICK:TCP_port=" +
		std::to_string(sick);
	// The same simulated scanner served as both devices, at the LMS1xx's
	// 25 Hz (CLMS100Eth asks for it); the clock starts when both stream
	// (CLMS100Eth takes ~15 s to set its device up).
	const CommandResult r = runCommand(
		emulatorCommand(prefix, laser, odo,
			"--sick-port " + std::to_string(sick) + " --set Laser:rate=25") +
		shellQuote(kLive) + " " + liveArgs(laser, odo) + both +
		" --duration 4 --out " + shellQuote(out) + " --set Evaluation:ground_truth=" +
		shellQuote(prefix + ".served.gt.txt") +
		"; code=$?; kill -TERM $emu; wait $emu; echo exit=$code");
	ASSERT_NE(r.output.find("exit=0"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("takes them right to left"), std::string::npos) << r.output;

	const auto s = readJson(out + "/summary.json");
	const auto& hokuyo = s["live"]["sensors"][0];
	const auto& lms = s["live"]["sensors"][1];
	EXPECT_EQ(lms["driver"], "CLMS100Eth");
#ifdef FEATLOC_SANITIZED_BUILD
	const double tolerance = 0.8;
#else
	const double tolerance = 0.15;	// CLMS100Eth polls: ~24 of 25 scans
#endif
	EXPECT_NEAR(hokuyo["rate_hz"].get<double>(), 25.0, 25.0 * tolerance);
	EXPECT_NEAR(lms["rate_hz"].get<double>(), 25.0, 25.0 * tolerance);
	// As with one laser: a reading may come late when ctest's other tests
	// load both cores (one in 7 full runs had one); at most 1% of them, and
	// each is kept in live-late.rawlog (counted below).
	const size_t late = s["live"]["late_observations"].get<size_t>();
	const size_t received = hokuyo["received"].get<size_t>() + lms["received"].get<size_t>() +
		s["live"]["sensors"][2]["received"].get<size_t>();
	EXPECT_LE(100 * late, received) << late << " late";
	EXPECT_EQ(lms["driver_errors"], 0);
	EXPECT_LT(s["evaluation"]["ate_m"]["rmse"].get<double>(), 0.05) << s.dump(1);

	// Both lasers recorded (a late scan in live-late.rawlog), the SICK's
	// scans as the device sends them.
	RawlogEntry e;
	size_t hokuyoScans = 0, sickScans = 0, sickRightToLeft = 0;
	for (const std::string file : {"/live.rawlog", "/live-late.rawlog"})
	{
		if (file == "/live-late.rawlog" && late == 0) break;
		RawlogReader reader(out + file);
		while (reader.next(e))
			if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(e.object))
			{
				const bool isSick = scan->sensorLabel == "SICK";
				(isSick ? sickScans : hokuyoScans)++;
				sickRightToLeft += isSick && scan->rightToLeft;
			}
	}
	EXPECT_EQ(hokuyoScans, hokuyo["received"].get<size_t>());
	EXPECT_EQ(sickScans, lms["received"].get<size_t>());
	EXPECT_EQ(sickRightToLeft, sickScans);

	// featloc-run replays the recording (matching the Hokuyo's scans) to
	// the same poses.
	const CommandResult rr = runCommand(shellQuote(kRun) + " " + shellQuote(kConfig) + " " +
		shellQuote(out + "/live.rawlog") + " -q --out " + shellQuote(replay) + both);
	ASSERT_EQ(rr.exitCode, 0) << rr.output;
	const auto a = dataRows(out + "/trajectory.tum"), b = dataRows(replay + "/trajectory.tum");
	ASSERT_FALSE(a.empty());
	EXPECT_EQ(a, b);
}

TEST(Live, CtrlCPassesOnAndRecordsEveryObservationReceived)
{
	TempDir dir;
	const unsigned short laser = freePort(), odo = freePort();
	const std::string out = dir.file("live"), prefix = dir.file("emu");
	// The emulator stops first (it reports what it delivered), then
	// featloc-live gets Ctrl-C: all of it must be in live.rawlog.
	const CommandResult r = runCommand(emulatorCommand(prefix, laser, odo) +
		shellQuote(kLive) + " " + liveArgs(laser, odo) + " --out " + shellQuote(out) +
		" > /dev/null 2>&1 & live=$!; sleep 4; kill -TERM $emu; wait $emu; sleep 0.5; "
		"kill -INT $live; wait $live; echo exit=$?; cat " + shellQuote(prefix + ".out"));
	ASSERT_NE(r.output.find("exit=0"), std::string::npos) << r.output;
	const Delivered sent = emulatorDelivered(r.output);
	EXPECT_GT(sent.scans, 100u);
	const Recorded rec = countRecorded(out + "/live.rawlog");
	const Recorded late = countRecorded(out + "/live-late.rawlog");
	EXPECT_EQ(rec.scans + late.scans, sent.scans);
	EXPECT_EQ(rec.odometry + late.odometry, sent.odometry);
	EXPECT_EQ(readJson(out + "/summary.json")["live"]["stopped_by"], "Ctrl-C / SIGTERM");
}

TEST(Live, DeviceFaultsMidRunAreReportedAndRecoveredWithNothingReceivedLost)
{
	TempDir dir;
	const unsigned short laser = freePort(), odo = freePort();
	const std::string out = dir.file("live"), prefix = dir.file("emu");
	// The link drops for 1.5 s (connections refused), a malformed frame
	// comes, then the device hangs with its link up for 3 s.
	const CommandResult r = runCommand(
		emulatorCommand(prefix, laser, odo,
			"--laser-fault outage@2:1.5 --laser-fault garbage@5 --laser-fault stall@6:3") +
		shellQuote(kLive) + " " + liveArgs(laser, odo) +
		" --set Live:restart_after_silence=1.5 --set Evaluation:ground_truth=" +
		shellQuote(prefix + ".served.gt.txt") + " --out " + shellQuote(out) + " > " +
		shellQuote(dir.file("live.txt")) + " 2>&1 & live=$!; sleep 12; kill -TERM $emu; "
		"wait $emu; sleep 0.5; kill -INT $live; wait $live; echo exit=$?; cat " +
		shellQuote(prefix + ".out"));
	ASSERT_NE(r.output.find("exit=0"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("3 faults injected"), std::string::npos) << r.output;
	const std::string console = readText(dir.file("live.txt"));
	// Nothing received is lost, before, between or after the faults.
	const Delivered sent = emulatorDelivered(r.output);
	const Recorded rec = countRecorded(out + "/live.rawlog");
	const Recorded late = countRecorded(out + "/live-late.rawlog");
	EXPECT_EQ(rec.scans + late.scans, sent.scans) << console;
	EXPECT_EQ(rec.odometry + late.odometry, sent.odometry);
	// Scans came back after the stall: before it (6 s at 40 Hz, 1.5 s of
	// them out) the device could send at most 180.
	EXPECT_GT(rec.scans, 200u) << console;
	// Each fault is said as it happens: the silence, the driver's own
	// words on the malformed frame, the restart of the hung device, and
	// the return of the scans after the outage and after the stall.
	for (const std::string& s :
		 {std::string("[LASER] CHokuyoURG: no observation for 1 s"),
			 std::string("Expected 3247 data bytes"),
			 std::string("driver restarted: no observation for 1.5 s without an error")})
		EXPECT_NE(console.find(s), std::string::npos) << s << "\n" << console;
	std::vector<double> gaps;
	const std::regex again("observations again after ([0-9.]+) s");
	for (auto it = std::sregex_iterator(console.begin(), console.end(), again);
		 it != std::sregex_iterator(); ++it)
		gaps.push_back(std::stod((*it)[1]));
	ASSERT_EQ(gaps.size(), 2u) << console;
	EXPECT_GT(gaps[0], 1.4);  // the outage
	EXPECT_GT(gaps[1], 2.9);  // the stall
	const auto summary = readJson(out + "/summary.json");
	const auto& laserReport = summary["live"]["sensors"][0];
	EXPECT_EQ(laserReport["section"], "LASER");
	EXPECT_GE(laserReport["restarts"].get<int>(), 2);
	EXPECT_GE(laserReport["driver_errors"].get<int>(), 1);
	EXPECT_NEAR(laserReport["longest_gap_s"].get<double>(), gaps[1], 0.06);	// said to 0.1 s
	// The pose is tracked through it all (odometry bridges the gaps).
	EXPECT_LT(summary["evaluation"]["ate_m"]["rmse"].get<double>(), 0.05)
		<< summary.dump(1);
}

TEST(DeviceFault, ParsesTheDocumentedFormsAndRejectsOthers)
{
	const DeviceFault outage = DeviceFault::parse("outage@2:1.5");
	EXPECT_EQ(outage.kind, DeviceFault::Kind::Outage);
	EXPECT_DOUBLE_EQ(outage.at, 2.0);
	EXPECT_DOUBLE_EQ(outage.duration, 1.5);
	EXPECT_EQ(DeviceFault::parse("stall@6:3").kind, DeviceFault::Kind::Stall);
	EXPECT_EQ(DeviceFault::parse("garbage@5").kind, DeviceFault::Kind::Garbage);
	for (const char* bad : {"outage@2", "garbage", "flood@1", "stall@x:1", "outage@-1:2",
			 "garbage@nan", "outage@1:2s"})
		EXPECT_THROW(DeviceFault::parse(bad), std::invalid_argument) << bad;
	// On the command line: a usage error (exit 2) naming the option.
	const CommandResult r = runCommand(shellQuote(kSim) + " " + shellQuote(kWorld) +
		" --out /tmp/featloc-unused --serve --laser-fault flood@1");
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_NE(r.output.find("--laser-fault 'flood@1': unknown fault"), std::string::npos)
		<< r.output;
}

TEST(Live, ADeviceThatNeverAnswersIsAnErrorNamingItsSectionAndAddress)
{
	TempDir dir;
	const unsigned short port = freePort();
	ScipLaserServer silent({}, port, ScipLaserServer::Fault::Silent);
	const auto t0 = std::chrono::steady_clock::now();
	const CommandResult r = runCommand(shellQuote(kLive) + " " + liveArgs(port, freePort()) +
		" --set Live:sensors=LASER --set Live:startup_timeout=2 --out " +
		shellQuote(dir.file("out")));
	const double secs =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	EXPECT_EQ(r.exitCode, 1) << r.output;
	EXPECT_LT(secs, 15.0);
	for (const std::string& s : {std::string("[LASER] driver CHokuyoURG"),
			 "PORT_DIR=" + std::to_string(port), std::string("IP_DIR=127.0.0.1"),
			 std::string("startup_timeout")})
		EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
	EXPECT_FALSE(fs::exists(dir.file("out")));	// a failed start writes nothing
}

TEST(Live, NothingListeningIsAnErrorWithTheDriversReason)
{
	TempDir dir;
	const unsigned short port = freePort();
	const CommandResult r = runCommand(shellQuote(kLive) + " " + liveArgs(freePort(), port) +
		" --set Live:sensors=ODOMETRY --set Live:startup_timeout=2 --out " +
		shellQuote(dir.file("out")));
	EXPECT_EQ(r.exitCode, 1) << r.output;
	EXPECT_NE(r.output.find("[ODOMETRY] driver TcpOdometrySensor"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("port=" + std::to_string(port)), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("Connection refused"), std::string::npos) << r.output;
	EXPECT_FALSE(fs::exists(dir.file("out")));
}

TEST(Live, AnUnknownDriverOrKeyIsAConfigError)
{
	TempDir dir;
	CommandResult r = runCommand(shellQuote(kLive) + " " + liveArgs(1, 2) +
		" --set LASER:driver=CHokuyoURGX --out " + shellQuote(dir.file("out")));
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_NE(r.output.find("driver = CHokuyoURGX: not an MRPT sensor driver"), std::string::npos)
		<< r.output;
	r = runCommand(shellQuote(kLive) + " " + liveArgs(1, 2) + " --set ODOMETRY:prot=1 --out " +
		shellQuote(dir.file("out")));
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_NE(r.output.find("prot"), std::string::npos) << r.output;
	EXPECT_FALSE(fs::exists(dir.file("out")));
}

TEST(Live, EveryLiveKeyIsInTheConfigReferenceDoc)
{
	featloc::test::expectEveryKeyDocumented(
		std::string(FEATLOC_SOURCE_DIR) + "/doc/config-reference.md",
		[](mrpt::config::CConfigFileBase& c) {
			LiveOptions live;
			live.sensors = {"LASER"};
			live.saveToConfigFile(c, LiveOptions::kSection);
		});
}
