// Radiance's view parameters (-vt -vp -vd -vu -vh -vv -vo -va -vs -vl), shared by rpict, rtrace and vwrays:
// parsing from an argument list or from a view string (the VIEW= line of a picture header, a view file's
// `rvu -vtv ...` line), Radiance's checks and messages, the ray through a point of the image, and the option
// string written back. The formulas follow Radiance's src/common/image.c (setview, viewray).
#pragma once
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>

#include "geometry/ray.h"

namespace brume {

// The view types' letters, as after -vt.
enum ViewType : char {
    kPerspective = 'v',
    kParallel = 'l',
    kHemispherical = 'h',  // fisheye: image radius proportional to sin of the angle off -vd
    kAngular = 'a',        // fisheye: image radius proportional to the angle off -vd
    kPlanisphere = 's',    // stereographic fisheye: image radius proportional to tan of half the angle
    kCylindrical = 'c',    // panorama: horizontal angle across, perspective up and down
};

// The ray through one point of the image.
struct ViewRay {
    dvec3 org;  // on the fore clipping plane (-vo), or the view point when -vo is 0
    dvec3 dir;  // unit length
    // How far along `dir` from `org` the scene is seen: the aft clipping plane (-va), infinity when -va is 0.
    double tmax = std::numeric_limits<double>::infinity();
};

struct View {
    char type = kPerspective;
    dvec3 vp{0, 0, 0};  // view point
    dvec3 vd{0, 1, 0};  // view direction, kept as given (its length is printed back, as Radiance does)
    dvec3 vu{0, 0, 1};  // view up
    double vh = 45;     // horizontal size: degrees, or world units for a parallel view
    double vv = 45;     // vertical size
    double vo = 0;      // fore clipping distance
    double va = 0;      // aft clipping distance; 0 for none
    double vs = 0;      // horizontal shift, in image widths
    double vl = 0;      // vertical lift, in image heights

    // Radiance's setview checks: an empty string for a usable view, else Radiance's message
    // ("view up parallel to view direction", "illegal horizontal view size", ...).
    std::string problem() const;
    // Throws Error with problem()'s message when there is one.
    void validate() const;

    // The ray through image point (x, y), each in [0, 1] from the left and bottom edges, with -vs and -vl
    // shifting the image; nullopt where a fisheye's projection reaches no direction (beyond 90° off axis for
    // -vth, 180° for -vta; Radiance's angular fisheye does give rays in the corners outside its circle), and
    // for an invalid view.
    std::optional<ViewRay> ray(double x, double y) const;
    // The inverse of ray() (Radiance's viewloc): the image point (x, y) whose ray passes through world point
    // p, outside [0, 1] when p is outside the picture; nullopt when p is behind the view (or at a fisheye's
    // blind direction) and for an invalid view. Clipping distances are ignored.
    std::optional<glm::dvec2> location(const dvec3& p) const;

    // The height over the width of the view's image (Radiance's viewaspect): tan(vv/2)/tan(vh/2) for a
    // perspective view, vv/vh for a parallel or angular one, the ratio of the image-plane extents for the
    // others. Throws Error with problem()'s message for an invalid view.
    double aspect() const;

    // Radiance's full option string, as in a VIEW= header line: "-vtv -vp 0 0 0 -vd 0 1 0 ...", no leading
    // space.
    std::string options() const;

    bool operator==(const View&) const = default;
};

// Reads one view option at args[0] into `view` and returns how many arguments it used (the option and its
// values); 0 when args[0] is not a view option (-vf, which names a file, is left to the caller). Throws
// Error when a view option lacks its values or they are not numbers.
size_t parseViewOption(View& view, std::span<const std::string> args);

// Reads the view options in a string as Radiance's sscanview does: words that are not view options (a
// program name, "VIEW=") are skipped, as are malformed options. Returns how many view options were read.
int parseViewString(View& view, std::string_view text);

// Whether a header or view-file line holds a view: it starts with VIEW= or a program name that writes one
// (rpict, rvu, rpiece, rxpiece, pinterp, rview, or the running program, after any directory), as
// Radiance's isview decides.
bool isViewLine(std::string_view line);

}  // namespace brume
