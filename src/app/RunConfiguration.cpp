#include "featloc/app/RunConfiguration.h"

#include "featloc/config/ConfigValues.h"
#include "featloc/core/ConfigError.h"
#include "featloc/estimators/PoseEstimatorFactory.h"
#include "featloc/localization/LocalizationMapFile.h"
#include "featloc/localization/MapLocalizer.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/stereo/StereoLandmarkExtractorFactory.h"

namespace featloc
{
RunConfiguration RunConfiguration::load(const mrpt::config::CConfigFileBase& cfg)
{
	RunConfiguration rc;
	rc.input.loadFromConfigFile(cfg, InputOptions::kSection);
	rc.odometry.loadFromConfigFile(cfg, OdometryOptions::kSection);
	rc.pipeline.loadFromConfigFile(cfg, PipelineOptions::kSection);
	rc.estimator = PoseEstimatorFactory::createFromConfig(cfg, rc.pipeline.estimator);
	rc.output.loadFromConfigFile(cfg, OutputOptions::kSection);
	rc.evaluation.loadFromConfigFile(cfg, EvaluationOptions::kSection);
	rc.matcher = ScanMatcherFactory::createFromConfig(cfg);
	rc.stereo = StereoLandmarkExtractorFactory::createFromConfig(cfg);
	if (rc.stereo)
	{
		try
		{
			rc.estimator->setStereoLandmarks(rc.stereo);
		}
		catch (const ConfigError& e)
		{
			config::fail(cfg, StereoLandmarkExtractorFactory::kSection, "class", e.what());
		}
	}
	rc.localization.loadFromConfigFile(cfg, LocalizationOptions::kSection);
	if (rc.localization.enabled())
	{
		if (!rc.estimator->fusesAbsolutePoses())
			config::fail(cfg, LocalizationOptions::kSection, "map",
				"localization in a map needs [Pipeline] estimator = ekf (estimator '" +
					rc.estimator->name() + "' cannot fuse absolute poses)");
		ScanMatcher::Ptr mapMatcher;
		try
		{
			mapMatcher = ScanMatcherFactory::create(rc.localization.matcher_class.empty()
					? rc.matcher->className()
					: rc.localization.matcher_class);
		}
		catch (const ConfigError& e)
		{
			config::fail(cfg, LocalizationOptions::kSection, "matcher_class", e.what());
		}
		mapMatcher->loadParams(cfg, ScanMatcherFactory::paramsSection(mapMatcher->className()));
		mapMatcher->coarseSearchOptions().enabled = rc.localization.map_coarse_search;
		mapMatcher->setGuessGateEnabled(rc.localization.map_guess_gate);
		auto map = std::make_shared<LocalizationMap>(LocalizationMapFile::load(rc.localization));
		rc.mapLocalizer = std::make_shared<MapLocalizer>(
			map, mapMatcher, rc.localization, rc.pipeline.global_start);
	}
	else if (rc.pipeline.global_start)
		config::fail(cfg, PipelineOptions::kSection, "initial_pose",
			"global: the pose is found in a known map, and [Localization] map is empty");
	return rc;
}

RunConfiguration RunConfiguration::defaults()
{
	RunConfiguration rc;
	rc.estimator = PoseEstimatorFactory::create(rc.pipeline.estimator);
	rc.matcher = ScanMatcherFactory::create(ScanMatcherFactory::kDefaultClass);
	return rc;
}

void RunConfiguration::save(mrpt::config::CConfigFileBase& cfg) const
{
	input.saveToConfigFile(cfg, InputOptions::kSection);
	odometry.saveToConfigFile(cfg, OdometryOptions::kSection);
	pipeline.saveToConfigFile(cfg, PipelineOptions::kSection);
	// Every estimator's section: the selected one's values, the others'
	// defaults (one reference ini documents every key).
	for (const auto& name : PoseEstimatorFactory::knownClassNames())
	{
		if (name == estimator->className())
			estimator->saveParams(cfg);
		else
			PoseEstimatorFactory::create(name)->saveParams(cfg);
	}
	config::write(
		cfg, ScanMatcherFactory::kSection, "class", matcher->className(),
		"scan matcher class; parameters in [ScanMatcher.<ClassName>]");
	for (const auto& name : ScanMatcherFactory::knownClassNames())
	{
		const std::string section = ScanMatcherFactory::paramsSection(name);
		if (name == matcher->className())
			matcher->saveParams(cfg, section);
		else
			ScanMatcherFactory::create(name)->saveParams(cfg, section);
	}
	config::write(cfg, StereoLandmarkExtractorFactory::kSection, "class",
		stereo ? stereo->className() : std::string(),
		"stereo landmark extractor (empty: none; needs estimator = ekf); parameters in [StereoLandmarks.<ClassName>]");
	for (const auto& name : StereoLandmarkExtractorFactory::knownClassNames())
	{
		const std::string section = StereoLandmarkExtractorFactory::paramsSection(name);
		if (stereo && name == stereo->className())
			stereo->saveParams(cfg, section);
		else
			StereoLandmarkExtractorFactory::create(name)->saveParams(cfg, section);
	}
	localization.saveToConfigFile(cfg, LocalizationOptions::kSection);
	output.saveToConfigFile(cfg, OutputOptions::kSection);
	evaluation.saveToConfigFile(cfg, EvaluationOptions::kSection);
}
}  // namespace featloc
