// Fuzz target: every registered scan matcher on arbitrary scans: 0 to
// 100,000 beams; ranges that are NaN, Inf, negative, zero or at max range;
// zero, negative or NaN apertures and max ranges; any validity flags; any
// initial guess and covariance. A matcher must return a result (success or
// a failure reason), never crash, hang or throw something else than
// featloc's errors, and its inspection must hold.
#include <fuzzer/FuzzedDataProvider.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstdint>

#include "featloc/core/ConfigError.h"
#include "featloc/core/InputError.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/registerClasses.h"

namespace
{
mrpt::obs::CObservation2DRangeScan makeScan(FuzzedDataProvider& in)
{
	mrpt::obs::CObservation2DRangeScan s;
	const size_t beams = in.ConsumeBool() ? in.ConsumeIntegralInRange<size_t>(0, 100000)
										  : in.ConsumeIntegralInRange<size_t>(0, 400);
	s.aperture = in.ConsumeFloatingPoint<float>();
	s.maxRange = in.ConsumeFloatingPoint<float>();
	s.rightToLeft = in.ConsumeBool();
	s.sensorPose = mrpt::poses::CPose3D(in.ConsumeFloatingPointInRange<double>(-1, 1),
		in.ConsumeFloatingPointInRange<double>(-1, 1), 0,
		in.ConsumeFloatingPointInRange<double>(-4, 4), 0, 0);
	s.resizeScan(beams);
	// Long scans repeat a short pattern, so that the input stays small.
	std::vector<float> pattern(std::max<size_t>(1, in.ConsumeIntegralInRange<size_t>(1, 64)));
	for (float& r : pattern) r = in.ConsumeFloatingPoint<float>();
	const uint64_t validBits = in.ConsumeIntegral<uint64_t>();
	for (size_t i = 0; i < beams; i++)
	{
		s.setScanRange(i, pattern[i % pattern.size()]);
		s.setScanRangeValidity(i, (validBits >> (i % 64)) & 1);
	}
	return s;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const bool registered = (featloc::registerClasses(), true);
	(void)registered;
	static const auto classes = featloc::ScanMatcherFactory::knownClassNames();
	FuzzedDataProvider in(data, size);
	const std::string cls = classes[in.ConsumeIntegralInRange<size_t>(0, classes.size() - 1)];
	const auto reference = makeScan(in);
	const auto current = makeScan(in);
	mrpt::poses::CPosePDFGaussian guess;
	guess.mean = mrpt::poses::CPose2D(in.ConsumeFloatingPoint<double>(),
		in.ConsumeFloatingPoint<double>(), in.ConsumeFloatingPoint<double>());
	for (int k = 0; k < 3; k++) guess.cov(k, k) = in.ConsumeFloatingPoint<double>();
	try
	{
		auto matcher = featloc::ScanMatcherFactory::create(cls);
		const auto r = matcher->match(reference, current, guess);
		if (!r.success && r.failureReason.empty()) __builtin_trap();  // a failure must say why
	}
	catch (const featloc::InputError&)
	{
	}
	catch (const featloc::ConfigError&)
	{
	}
	return 0;
}
