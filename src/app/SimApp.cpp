#include "featloc/localization/LocalizationMapFile.h"
#include "featloc/app/SimApp.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "featloc/app/AppMain.h"
#include "featloc/app/ConfigCommandLine.h"
#include "featloc/app/InterruptSignals.h"
#include "featloc/app/UsageError.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/pipeline/ProgressBar.h"
#include "featloc/registerClasses.h"
#include "featloc/sim/DeviceFault.h"
#include "featloc/sim/SimConfiguration.h"
#include "featloc/sim/OdometryLineServer.h"
#include "featloc/sim/RealTimeLogPlayer.h"
#include "featloc/sim/ScipLaserServer.h"
#include "featloc/sim/SickLaserServer.h"
#include "featloc/sim/Simulator.h"
#include "featloc/sim/WorldPlot.h"
#include "featloc/sim/WorldSceneWriter.h"

namespace featloc
{
namespace
{
unsigned short tcpPort(unsigned value, const char* option)
{
	if (value > 65535) throw UsageError(std::string(option) + " must be a TCP port (0-65535)");
	return static_cast<unsigned short>(value);
}

/** What --serve is told on the command line. */
struct ServeOptions
{
	unsigned laserPort = 10940, sickPort = 0, odometryPort = 10950;
	std::vector<DeviceFault> laserFaults;
	/** The stereo camera's recording for CCameraSensor (empty: no camera). */
	std::string cameraRawlog;
};

/** --serve: the simulated log, in real time, through emulated devices. */
void serve(const SimConfiguration& sc, const std::string& rawlog,
	const std::vector<mrpt::poses::CPose2D>& truths, const std::string& gtPath,
	const ServeOptions& options, bool quiet)
{
	if (!options.laserPort && !options.sickPort)
		throw UsageError("--serve needs a laser: --laser-port and --sick-port are both 0");
	// A driver that hangs up must not kill the emulator (SIGPIPE).
	std::signal(SIGPIPE, SIG_IGN);
	const auto items = RealTimeLogPlayer::load(rawlog, truths);
	std::printf("serving %s in real time:\n", rawlog.c_str());
	std::unique_ptr<ScipLaserServer> hokuyo;
	std::unique_ptr<SickLaserServer> sick;
	std::vector<EmulatedLaser*> lasers;
	if (options.laserPort)
	{
		const auto device = ScipLaserServer::deviceFor(sc.laser.beams, sc.laser.aperture,
			sc.laser.max_range, static_cast<int>(std::lround(sc.laser.rate)));
		hokuyo = std::make_unique<ScipLaserServer>(device, tcpPort(options.laserPort, "--laser-port"));
		lasers.push_back(hokuyo.get());
		std::printf("  laser: Hokuyo %s, SCIP 2.0 on 127.0.0.1:%u (%d beams, ARES %d, %d rpm)\n",
			device.model.c_str(), options.laserPort, device.amax - device.amin + 1, device.ares,
			device.scanRpm);
	}
	if (options.sickPort)
	{
		const auto device =
			SickLaserServer::deviceFor(sc.laser.beams, sc.laser.aperture, sc.laser.rate);
		sick = std::make_unique<SickLaserServer>(device, tcpPort(options.sickPort, "--sick-port"));
		lasers.push_back(sick.get());
		std::printf("  laser: SICK LMS1xx, CoLa-A on 127.0.0.1:%u (%d beams, %.2f deg, %.0f Hz; "
					"MRPT's CLMS100Eth takes about 15 s to set it up)\n",
			options.sickPort, device.beams(), device.resolution / 1e4, device.frequency / 100.0);
	}
	std::unique_ptr<OdometryLineServer> odometry;
	if (options.odometryPort)
		odometry = std::make_unique<OdometryLineServer>(
			tcpPort(options.odometryPort, "--odometry-port"));
	if (!options.cameraRawlog.empty())
		std::printf("  stereo camera: %s, written when the drivers are connected, each pair "
					"stamped on this computer's clock (MRPT's CCameraSensor with grabber_type = "
					"rawlog replays it)\n",
			options.cameraRawlog.c_str());
	std::printf("  odometry: %s\nwaiting for the drivers to connect...\n",
		odometry ? ("featloc line protocol on 127.0.0.1:" + std::to_string(options.odometryPort)).c_str()
				 : "none");
	std::fflush(stdout);
	InterruptSignals signals;
	RealTimeLogPlayer player(lasers, odometry.get(), gtPath);
	player.setLaserFaults(options.laserFaults);
	if (!options.cameraRawlog.empty()) player.setCameraRecording(options.cameraRawlog);
	for (const auto& f : options.laserFaults)
		std::printf("  laser fault to inject: %s\n", f.describe().c_str());
	ProgressBar progress(std::cerr, isatty(STDERR_FILENO) != 0);
	const auto r = player.play(items, &signals.flag(), [&](double f) {
		if (!quiet) progress.update(f, lasers.front()->scansSent());
	});
	if (!quiet) progress.done(lasers.front()->scansSent());
	std::printf("%s after %.1f s: %zu scans, %zu of %zu odometry readings delivered; %zu faults "
				"injected\n",
		r.stopped ? "stopped" : "log served", r.seconds, r.scans, r.readingsDelivered, r.readings,
		r.faultsInjected);
	if (!options.cameraRawlog.empty())
		std::printf("  stereo camera: %zu pairs in %s\n", r.stereoPairs, options.cameraRawlog.c_str());
	if (hokuyo)
		std::printf("  Hokuyo: %zu of them delivered (%zu skipped by the driver while it "
					"re-initialised the device), %zu connections\n",
			hokuyo->scansSent(), hokuyo->scansDiscardedByReinit(), hokuyo->connections());
	if (sick)
	{
		std::printf("  SICK: %zu of them polled by the driver, %zu polls answered with a scan "
					"sent already, %zu connections\n",
			sick->scansSent(), sick->scansResent(), sick->connections());
		if (!sick->configurationMismatch().empty())
			std::printf("  SICK: %s\n", sick->configurationMismatch().c_str());
	}
	std::printf("  truth: %s\n", gtPath.c_str());
}
}  // namespace

int SimApp::main(int argc, char** argv)
{
	registerClasses();
	TCLAP::CmdLine cmd(
		"featloc-sim: simulate a robot with a 2-D laser and odometry in a "
		"world of walls, obstacles and walking people; write an MRPT rawlog "
		"and the exact ground truth. See doc/simulator.md for the world file.",
		' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> argWorld(
		"world", "World file (.ini, or .yaml with the same sections)", false,
		"", "WORLD", cmd);
	TCLAP::ValueArg<std::string> argOut(
		"o", "out",
		"Output prefix: writes PREFIX.rawlog, PREFIX.gt.txt, PREFIX.3Dscene, "
		"PREFIX.png",
		false, "", "PREFIX", cmd);
	TCLAP::ValueArg<unsigned int> argSeed(
		"", "seed", "Random seed; overrides [Simulation] seed", false, 1, "N", cmd);
	TCLAP::SwitchArg argServe("", "serve",
		"After simulating, serve the log in real time as devices on 127.0.0.1: the "
		"laser as a Hokuyo in SCIP 2.0 (MRPT's CHokuyoURG with IP_DIR/PORT_DIR) and "
		"the odometry in featloc's line protocol (featloc-live's TcpOdometrySensor); "
		"writes PREFIX.served.gt.txt, the truth on this computer's clock, and, when the "
		"world has a stereo camera, PREFIX.camera.rawlog for MRPT's CCameraSensor "
		"(grabber_type = rawlog). Forces [Simulation] format = 2. Ctrl-C stops.",
		cmd);
	TCLAP::ValueArg<unsigned> argLaserPort("", "laser-port",
		"--serve: the Hokuyo's TCP port (0: no Hokuyo, with --sick-port)", false, 10940, "PORT",
		cmd);
	TCLAP::ValueArg<unsigned> argSickPort("", "sick-port",
		"--serve: also serve the laser as a SICK LMS1xx in CoLa-A on this TCP port (MRPT's "
		"CLMS100Eth with ip_address/TCP_port; it asks for 1081 beams over 270 deg at 25 Hz); "
		"0: none",
		false, 0, "PORT", cmd);
	TCLAP::ValueArg<unsigned> argOdometryPort("", "odometry-port",
		"--serve: the odometry's TCP port (0: a robot without odometry)", false, 10950,
		"PORT", cmd);
	TCLAP::ValueArg<double> argGridmap("", "gridmap",
		"Also write the world's walls and obstacles as an MRPT occupancy grid, PREFIX.gridmap.gz, "
		"with cells of this size [m] (a known map for pf-localization and featloc-run's "
		"[Localization] map)",
		false, 0, "METRES", cmd);
	TCLAP::MultiArg<std::string> argLaserFault("", "laser-fault",
		"--serve: inject a laser fault at a time of the log [s]: outage@T:D (the link "
		"drops and connections are refused for D s), stall@T:D (link up, the device "
		"sends and answers nothing for D s) or garbage@T (a malformed scan); repeatable",
		false, "FAULT", cmd);
	TCLAP::SwitchArg argFrozen("", "frozen",
		"Simulate the world with nothing moving: no [Agent.*], every [Door.*] held where "
		"it is at t = 0; the robot's path, the odometry and the laser are the same. A "
		"matcher's error on this log against the world's own (featloc-bench) is what the "
		"moving things cost it",
		cmd);
	ConfigCommandLine config(cmd, "Laser:preset=hokuyo_utm30lx",
		"the settings sections with every key, default and unit");
	int exitCode = 0;
	if (!parseCommandLine(cmd, argc, argv, exitCode)) return exitCode;

	if (config.writeConfigIfAsked(
			"# featloc-sim settings: every key with its default. Add\n"
			"# [Wall.<name>], [Obstacle.<name>] and [Agent.<name>] sections\n"
			"# (doc/simulator.md).\n",
			[](mrpt::config::CConfigFileBase& c) { SimConfiguration().saveSettings(c); }))
		return 0;
	if (argWorld.getValue().empty()) throw UsageError("missing WORLD (the world file)");
	if (!argOut.isSet()) throw UsageError("missing --out PREFIX");

	ServeOptions serveOptions;
	serveOptions.laserPort = argLaserPort.getValue();
	serveOptions.odometryPort = argOdometryPort.getValue();
	serveOptions.sickPort = argSickPort.getValue();
	for (const auto& spec : argLaserFault.getValue())
	{
		try
		{
			serveOptions.laserFaults.push_back(DeviceFault::parse(spec));
		}
		catch (const std::invalid_argument& e)
		{
			throw UsageError(std::string("--laser-fault ") + e.what());
		}
	}
	if (!serveOptions.laserFaults.empty() && !argServe.getValue())
		throw UsageError("--laser-fault needs --serve");
	if (argGridmap.isSet() && !(argGridmap.getValue() >= 0.005 && argGridmap.getValue() <= 1))
		throw UsageError("--gridmap needs a cell size in [0.005, 1] m");

	TrackedConfig cfg;
	config.load(cfg, argWorld.getValue());
	SimConfiguration sc = SimConfiguration::load(cfg);
	cfg.requireAllKeysRead();
	if (argSeed.isSet()) sc.simulation.seed = argSeed.getValue();
	if (argFrozen.getValue()) sc.world = sc.world.frozen();
	if (argServe.getValue()) sc.simulation.format = 2;	// odometry readings to serve

	const std::string prefix = argOut.getValue();
	const auto parent = std::filesystem::path(prefix).parent_path();
	if (!parent.empty()) std::filesystem::create_directories(parent);
	const std::string rawlog = prefix + ".rawlog", gt = prefix + ".gt.txt",
					  scene = prefix + ".3Dscene", picture = prefix + ".png";

	const auto t0 = std::chrono::steady_clock::now();
	Simulator sim(
		sc.world, sc.robot, sc.laser, sc.odometry, sc.simulation, sc.beacons, sc.stereo);
	ProgressBar progress(std::cerr, isatty(STDERR_FILENO) != 0);
	size_t scans = 0;
	std::vector<mrpt::poses::CPose2D> truths;
	const auto res = sim.run(
		rawlog, gt,
		[&](const SimulatedScan& s) {
			scans++;
			truths.push_back(s.robot);
		},
		[&](double f) {
			if (!config.quiet()) progress.update(f, scans);
		});
	if (!config.quiet()) progress.done(res.scans);
	WorldSceneWriter::write(scene, sim.world(), sim.trajectory());
	WorldPlot::write(
		picture, sim.world(), sim.trajectory(),
		std::filesystem::path(argWorld.getValue()).filename().string() +
			": robot path " + std::to_string(static_cast<int>(res.pathLength)) +
			" m, " + std::to_string(res.scans) + " scans");
	if (argGridmap.isSet())
	{
		// The walls as featloc-run draws a world file for [Localization]
		// map, written in MRPT's grid frame. The drawn grid is shifted by
		// half a cell so that walls on round coordinates run through cell
		// centres; MRPT's frame puts cell edges there, so such a wall
		// occupies the cells on its +x / +y side: the drawn grid's cells,
		// one for one. (Re-binning the drawn cells' centres, which lie on
		// the edges, with x2idx put some into the neighbouring cell: walls
		// with a hole every few cells, through which MRPT's virtual beams
		// and pf-localization's likelihood passed.)
		LocalizationOptions lo;
		lo.map = argWorld.getValue();
		lo.grid_resolution = argGridmap.getValue();
		const LocalizationMap map = LocalizationMapFile::load(lo);
		const mrpt::maps::COccupancyGridMap2D& grid = map.grid();
		mrpt::io::CFileGZOutputStream f(prefix + ".gridmap.gz");
		mrpt::serialization::archiveFrom(f) << grid;
	}
	const double secs =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

	const size_t carts = static_cast<size_t>(std::count_if(sim.world().agents().begin(),
		sim.world().agents().end(),
		[](const WalkingAgent& a) { return a.params().shape == WalkingAgent::Shape::Cart; }));
	std::printf(
		"featloc-sim: %s, seed %u\n"
		"  world: %zu wall segments, %zu circles, %zu people, %zu carts, %zu doors\n"
		"  robot: %.1f m in %.1f s; laser %s, %u beams at %.1f Hz\n"
		"  wrote %zu scans (rawlog format #%u, %s) in %.2f s:\n"
		"    %s\n    %s\n    %s\n    %s\n",
		argWorld.getValue().c_str(), sc.simulation.seed,
		sim.world().segments().size(), sim.world().circles().size(),
		sim.world().agents().size() - carts, carts, sim.world().doors().size(), res.pathLength,
		res.duration,
		sc.laser.preset.c_str(), sc.laser.beams, sc.laser.rate, res.scans,
		sc.simulation.format,
		sc.simulation.format == 1
			? (std::to_string(res.actions) + " odometry actions").c_str()
			: (std::to_string(res.odometryReadings) + " odometry readings").c_str(),
		secs, rawlog.c_str(), gt.c_str(), scene.c_str(), picture.c_str());
	if (sc.stereo.enabled)
	{
		const auto stem = std::filesystem::path(rawlog).stem().string();
		const auto dir = std::filesystem::path(rawlog).parent_path();
		std::printf(
			"  stereo '%s': %zu pairs %ux%u at %.1f Hz:\n    %s/ (images)\n"
			"    %s.camera.gt.txt, %s.edges.gt.txt, %s_GT/ (ground truth)\n",
			sc.stereo.label.c_str(), res.stereoFrames, sc.stereo.width, sc.stereo.height,
			sc.stereo.rate, (dir / (stem + "_Images")).string().c_str(), prefix.c_str(),
			prefix.c_str(), prefix.c_str());
	}
	if (argServe.getValue() && sc.stereo.enabled) serveOptions.cameraRawlog = prefix + ".camera.rawlog";
	if (argServe.getValue())
		serve(sc, rawlog, truths, prefix + ".served.gt.txt", serveOptions, config.quiet());
	return 0;
}
}  // namespace featloc
