#pragma once
namespace featloc
{
/** featloc-stereo-import FOLDER --out OUT.rawlog [--rectify] [--rate HZ]
 * [--times CSV] [--ground-truth TUM] [--label NAME]: a stereo rawlog from
 * a folder of real image pairs and their calibration (see
 * doc/stereo-import.md):
 *  - pairs: `left/` + `right/` subfolders with the same file names;
 *    `left*` + `right*` files with the same suffix; or EuRoC's
 *    `mav0/cam0|cam1/data.csv` layout;
 *  - calibration found in the folder: `stereo_left.yaml` +
 *    `stereo_right.yaml` (OpenCV/ROS), `sensorLeft.yaml` +
 *    `sensorRight.yaml` (Kimera), `mav0/cam0|cam1/sensor.yaml` (EuRoC);
 *  - time: EuRoC csv (ns), a --times csv in that form, 19-digit
 *    nanosecond file names, else frame number / --rate;
 *  - --rectify: MRPT's CStereoRectifyMap, the rectified calibration
 *    written with the images;
 *  - --ground-truth: TUM rows at the frames' times copied to OUT.gt.txt.
 * Images go to `OUT_Images/` (MRPT's external storage). */
class StereoImportApp
{
   public:
	int main(int argc, char** argv);
};
}  // namespace featloc
