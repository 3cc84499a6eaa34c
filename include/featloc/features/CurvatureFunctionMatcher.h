#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <cstdint>
#include <vector>

namespace featloc
{
/** CF-SMA2 of Nunez et al.'s CF-IDC (section III.B.1): pairs the curvature
 * functions of the current scan's segments with those of the reference
 * scan by their similarity
 *
 *   rho_ij = max_s IFFT[ conj(FFT[c_i]) FFT[r_j] ](s)                (eq. 7)
 *
 * the cross-correlation of two functions computed with OpenCV's cv::dft
 * (the paper writes the product without the conjugate; the correlation
 * needs it). Pairing is greedy: the most similar unpaired pair is taken
 * while its rho_ij >= U_c (linear correlation: in the order of rho times
 * sqrt(shorter length / longer length), so that a wall pairs with the same
 * wall rather than with a short straight piece that fits it as well).
 *
 * Functions of one power-of-two length (normalized sampling) are
 * correlated circularly, as in the paper; functions of different lengths
 * (metric sampling) are zero-padded to one power-of-two length of at least
 * twice the longest, which makes the correlation linear (no wrap-around).
 *
 * Normalisation (the paper gives none; the issue asks that identical
 * shapes give 1): each function is extended by a second channel, the
 * constant curvature_floor e over its own samples (its support), so that
 * two straight segments (eta ~ 0 up to noise) give ~1 instead of the
 * meaningless correlation of two noise vectors, and a straight segment and
 * a corner ~0. Circular (the paper):
 *   rho = max_s [corr(c, r)(s) + e^2 L] / sqrt((|c|^2 + e^2 L)(|r|^2 + e^2 L)).
 * Linear: normalised over the samples both functions cover at shift s
 * (n(s), the energies E_c(s), E_r(s) there, all by FFT), over the shifts
 * where that overlap covers at least half of the shorter function:
 *   rho = max_s [corr(c, r)(s) + e^2 n(s)] / sqrt((E_c(s) + e^2 n(s))(E_r(s) + e^2 n(s))).
 * Identical functions give 1 at the right shift; so does a wall seen
 * further along from the next pose, where both scans see it. */
class CurvatureFunctionMatcher
{
   public:
	struct Parameters : public mrpt::config::CLoadableOptions
	{
		double U_c = 0.4;  //!< minimum similarity of a pair (section IV.A)
		double curvature_floor = mrpt::DEG2RAD(1.0);  //!< [rad] e above

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c,
			const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c,
			const std::string& s) const override;
	};

	struct Match
	{
		uint32_t current = 0, reference = 0;  //!< function indices
		double similarity = 0;	//!< rho_ij
		/** c_i[k] best corresponds to r_j[k + shift] (mod L if circular). */
		int shift = 0;
	};

	CurvatureFunctionMatcher() = default;
	explicit CurvatureFunctionMatcher(const Parameters& p) : params(p) {}

	/** Similarities of every current/reference pair, then the greedy
	 * pairing into `out` (most similar first). Functions all of one
	 * power-of-two length are correlated circularly; otherwise linearly. */
	void match(
		const std::vector<std::vector<double>>& current,
		const std::vector<std::vector<double>>& reference, std::vector<Match>& out);
	/** Same, only for the pairs with allowed[i * reference.size() + j]
	 * set (the others get similarity 0 and are not correlated), circular
	 * or linear as told (circular needs one power-of-two length). */
	void match(
		const std::vector<std::vector<double>>& current,
		const std::vector<std::vector<double>>& reference, const std::vector<char>& allowed,
		bool circular, std::vector<Match>& out);

	/** rho of the last match(), row-major: current i, reference j at
	 * [i * reference.size() + j]; and the best shifts. */
	const std::vector<double>& lastSimilarity() const { return m_rho; }
	const std::vector<int>& lastShift() const { return m_shift; }

	Parameters params;

   private:
	std::vector<double> m_rho;
	std::vector<int> m_shift;
	std::vector<double> m_normC, m_normR, m_countC, m_countR;  // reused buffers
};
}  // namespace featloc
