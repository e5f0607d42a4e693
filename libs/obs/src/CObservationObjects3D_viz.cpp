// CObservationObjects3D as an mrpt::opengl::Visualizable: what RawLogViewer (MRPT 2.5.8,
// main_show_selected_object.cpp, "Generic visualizable object") draws in its 3D view.
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/ObjectStyle.h>

#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/stock_objects.h>

#include <iomanip>
#include <sstream>

namespace simp::obs {

void CObservationObjects3D::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
    auto robot = mrpt::opengl::stock_objects::CornerXYZSimple(0.5f, 2.0f);
    robot->setName("robot");
    o.insert(robot);
    auto camera = mrpt::opengl::stock_objects::CornerXYZSimple(0.25f, 2.0f);
    camera->setPose(m_camera_pose);
    camera->setName(sensorLabel.empty() ? "camera" : sensorLabel);
    o.insert(camera);
    for (std::size_t i = 0; i < m_detections.size(); ++i) {
        std::ostringstream label;
        label << classNameOf(m_detections[i]) << " " << std::fixed << std::setprecision(2) << m_detections[i].confidence;
        appendLabelledBox(boxInRobot(i), classColorRgb(m_detections[i].class_id, m_class_names), label.str(), o);
    }
}

}  // namespace simp::obs
