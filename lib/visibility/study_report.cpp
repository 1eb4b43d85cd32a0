#include "visibility/study_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "io/picture.h"
#include "spectrum/colorimetry.h"
#include "util/pending_file.h"

namespace brume {

namespace {

// A number as the CSV writes it (%.*g), or nothing where there is none.
std::string number(double v, int digits = 4) {
    if (!std::isfinite(v)) return "";
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return text;
}

const char* quotedName(QuotedExtinction quoted) { return quoted == QuotedExtinction::At633nm ? "633nm" : "photopic"; }

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if (static_cast<unsigned char>(c) < 0x20) {
            char e[8];
            std::snprintf(e, sizeof e, "\\u%04x", c);
            out += e;
        } else out += c;
    }
    return out + "\"";
}

const char* const kCsvHead =
    "instant_s,observer,x,y,z,sign,kind,distance_m,sign_cd_m2,background_cd_m2,contrast,size_arcmin,"
    "threshold_cd_m2,visibility_level,verdict,seen_share,optical_depth,mean_extinction_1_m,jin_distance_m,"
    "jin_verdict,visibility_level_se,extinction_quoted,data_share,local_visibility_m,local_verdict,"
    "legibility_distance_m,legible\n";

}  // namespace

StudyReport::StudyReport(const VisibilityStudy& study, std::FILE* csv, ReportSettings settings)
    : study_(study), csv_(csv), settings_(std::move(settings)) {
    std::fputs(kCsvHead, csv_);
}

void StudyReport::writeRow(double time, size_t line, const SightLine& s) const {
    const Observer& o = study_.observerOf(line);
    const Sign& sign = study_.signOf(line);
    const SightMeasure& m = s.measure;
    const SightJudgement& j = s.judgement;
    // No luminances where no light was traced to the sign (behind it, or Jin's law alone), no level where the sign
    // was not seen.
    const bool behind = j.verdict == Verdict::Behind || study_.settings().jinOnly,
               judged = !behind && j.verdict != Verdict::Hidden;
    const double none = std::numeric_limits<double>::quiet_NaN();
    std::fprintf(csv_, "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n",
                 number(time, 10).c_str(), o.name.c_str(), number(o.eye.x, 10).c_str(), number(o.eye.y, 10).c_str(),
                 number(o.eye.z, 10).c_str(), sign.name.c_str(),
                 signKindName(sign.kind), number(m.distance).c_str(),
                 number(behind ? none : m.signLuminance, 5).c_str(),
                 number(behind ? none : m.backgroundLuminance, 5).c_str(), number(judged ? j.contrast : none).c_str(),
                 number(j.verdict == Verdict::Behind ? none : j.angularSize).c_str(), number(judged ? j.threshold : none).c_str(),
                 number(judged ? j.visibilityLevel : none).c_str(), verdictName(j.verdict),
                 number(m.seenShare, 3).c_str(), number(m.opticalDepth).c_str(), number(j.meanExtinction).c_str(),
                 number(j.jinDistance).c_str(), j.jinVisible ? "visible" : j.jinNoData ? "no-data" : "not-visible",
                 number(judged ? j.levelError : none, 3).c_str(), quotedName(study_.settings().quoted),
                 number(m.coverage, 3).c_str(), number(j.localVisibility).c_str(),
                 j.localEnough ? "enough" : "short", number(m.legibilityDistance).c_str(), j.legible ? "yes" : "no");
}

void StudyReport::instant(double time, const std::vector<SightLine>& lines) {
    std::vector<double> levels(lines.size()), coverage(lines.size());
    for (size_t line = 0; line < lines.size(); ++line) {
        writeRow(time, line, lines[line]);
        const SightJudgement& j = lines[line].judgement;
        levels[line] = j.verdict == Verdict::Visible || j.verdict == Verdict::BelowThreshold ? j.visibilityLevel : 0;
        coverage[line] = lines[line].measure.coverage;
    }
    std::fflush(csv_);
    // The summary: per sign, and for any sign, how many observers see it.
    const size_t signs = study_.signs().size(), observers = study_.observers().size();
    std::vector<int> light(signs + 1), jin(signs + 1), noData(signs + 1);
    for (size_t o = 0; o < observers; ++o) {
        bool anyLight = false, anyJin = false, anyNoData = false;
        for (size_t s = 0; s < signs; ++s) {
            const SightJudgement& j = lines[o * signs + s].judgement;
            const bool l = j.verdict == Verdict::Visible, n = j.verdict == Verdict::NoData || j.jinNoData;
            light[s] += l, jin[s] += j.jinVisible, noData[s] += n;
            anyLight = anyLight || l, anyJin = anyJin || j.jinVisible, anyNoData = anyNoData || n;
        }
        light[signs] += anyLight, jin[signs] += anyJin, noData[signs] += anyNoData;
    }
    for (size_t s = 0; s <= signs; ++s) {
        const double n = double(std::max<size_t>(observers, 1));
        summary_ += number(time, 10) + "," + (s < signs ? study_.signs()[s].sign.name : std::string("any")) + "," +
                    std::to_string(observers) + "," + std::to_string(light[s]) + "," + std::to_string(jin[s]) + "," +
                    std::to_string(noData[s]) + "," + number(light[s] / n, 4) + "," + number(jin[s] / n, 4) + "\n";
    }
    if (settings_.prefix.empty() || !settings_.grid) return;
    char suffix[64];
    std::snprintf(suffix, sizeof suffix, "_%g.hdr", time);
    const std::string at = " at t = " + number(time, 10) + " s";
    writeMaps(suffix, "visibility level" + at + " (0: hidden, behind or no data)", levels);
    if (std::any_of(coverage.begin(), coverage.end(), [](double c) { return c < 1; }))
        writeMaps("_data" + std::string(suffix), "share of the line with smoke data" + at, coverage);
}

// A map over the grid: one value per observer.
void StudyReport::writeMap(const std::string& path, const std::string& what, const std::vector<double>& values) const {
    const ObserverGrid& g = *settings_.grid;
    Picture p;
    p.width = g.columns, p.height = g.rows;
    p.pixels.assign(size_t(p.width) * size_t(p.height) * 3, 0.f);
    for (size_t o = 0; o < study_.observers().size(); ++o) {
        const Observer& ob = study_.observers()[o];
        for (int c = 0; c < 3; ++c) p.at(ob.column, ob.row)[c] = float(std::max(0.0, values[o]));
    }
    p.header = {settings_.command, "VISMAP=" + what,
                "VISMAP_GRID= x0 " + std::to_string(g.x0) + " y0 " + std::to_string(g.y0) + " step " +
                    std::to_string(g.step) + " (column 0 at x0, row 0 at the largest y)"};
    writeWhole(path, [&](std::ostream& out) { writeRadiancePicture(out, p); });
}

// One map per sign: values[line] of each observer.
void StudyReport::writeMaps(const std::string& suffix, const std::string& what, const std::vector<double>& values) const {
    const size_t signs = study_.signs().size(), observers = study_.observers().size();
    for (size_t s = 0; s < signs; ++s) {
        std::vector<double> sign(observers);
        for (size_t o = 0; o < observers; ++o) sign[o] = values[o * signs + s];
        const std::string& name = study_.signs()[s].sign.name;
        writeMap(settings_.prefix + "_" + name + suffix, what + " of sign " + name, sign);
    }
}

void StudyReport::finish(const Endurance& endurance) {
    if (settings_.prefix.empty()) return;
    writeWhole(settings_.prefix + "_summary.csv", [&](std::ostream& out) {
        out << "instant_s,sign,observers,visible_light,visible_jin,no_data,share_visible_light,share_visible_jin\n"
            << summary_;
    });
    writeLosses(endurance);
    writeJson();
    if (!settings_.grid) return;
    const size_t lines = study_.lines();
    std::vector<double> light(lines), jin(lines);
    for (size_t line = 0; line < lines; ++line)
        light[line] = Endurance::until(endurance.light(line)), jin[line] = Endurance::until(endurance.jin(line));
    const std::string until = "the last instant (s) through which it stayed visible from the first (0: not then)";
    writeMaps("_until.hdr", "by the light, " + until, light);
    writeMaps("_jin_until.hdr", "by Jin's law, " + until, jin);
    // ASET-style: how long some sign, any of the study's, stayed in sight from each cell.
    std::vector<double> anyLight, anyJin;
    for (size_t o = 0; o < study_.observers().size(); ++o)
        anyLight.push_back(Endurance::until(endurance.anyLight(o))), anyJin.push_back(Endurance::until(endurance.anyJin(o)));
    const std::string anyUntil = "the last instant (s) through which some sign stayed visible from the first (0: none then)";
    writeMap(settings_.prefix + "_any_until.hdr", "by the light, " + anyUntil, anyLight);
    writeMap(settings_.prefix + "_any_jin_until.hdr", "by Jin's law, " + anyUntil, anyJin);
}

void StudyReport::writeLosses(const Endurance& endurance) const {
    writeWhole(settings_.prefix + "_lost.csv", [&](std::ostream& out) {
        out << "observer,x,y,z,sign,criterion,how,lost_s,after_s,before_s\n";
        auto row = [&](const Observer& o, const std::string& sign, const char* criterion, const Loss& l) {
            const bool known = l.kind == Loss::Kind::Interpolated, after = l.kind != Loss::Kind::AtFirst,
                       before = l.kind != Loss::Kind::Never;
            out << o.name << ',' << number(o.eye.x, 10) << ',' << number(o.eye.y, 10) << ',' << number(o.eye.z, 10)
                << ',' << sign << ',' << criterion << ',' << lossKindName(l.kind) << ','
                << (known ? number(l.at, 6) : "") << ',' << (after ? number(l.after, 10) : "") << ','
                << (before ? number(l.before, 10) : "") << '\n';
        };
        const size_t signs = study_.signs().size();
        for (size_t o = 0; o < study_.observers().size(); ++o) {
            const Observer& ob = study_.observers()[o];
            for (size_t s = 0; s < signs; ++s) {
                row(ob, study_.signs()[s].sign.name, "light", endurance.light(o * signs + s));
                row(ob, study_.signs()[s].sign.name, "jin", endurance.jin(o * signs + s));
            }
            row(ob, "any", "light", endurance.anyLight(o));
            row(ob, "any", "jin", endurance.anyJin(o));
        }
        if (settings_.grid) return;
        // Waypoints are a route: it is lost where its first waypoint loses every sign (the earliest instant known
        // without one), named "route:" and that waypoint.
        for (const char* criterion : {"light", "jin"}) {
            const bool light = std::string(criterion) == "light";
            size_t first = 0;
            for (size_t o = 0; o < study_.observers().size(); ++o) {
                const Loss &a = light ? endurance.anyLight(o) : endurance.anyJin(o),
                           &b = light ? endurance.anyLight(first) : endurance.anyJin(first);
                if (a.kind != Loss::Kind::Never && (b.kind == Loss::Kind::Never || a.before < b.before)) first = o;
            }
            Observer route = study_.observers()[first];
            route.name = "route:" + route.name;
            row(route, "any", criterion, light ? endurance.anyLight(first) : endurance.anyJin(first));
        }
    });
}

void StudyReport::writeJson() const {
    const StudySettings& s = study_.settings();
    const VisibilityCriteria& c = s.criteria;
    std::ostringstream j;
    j << "{\n  \"program\": \"vismap\",\n  \"version\": " << jsonString(std::string("Brume ") + BRUME_VERSION)
      << ",\n  \"command\": " << jsonString(settings_.command) << ",\n  \"instants_s\": [";
    for (size_t i = 0; i < settings_.instants.size(); ++i) j << (i ? ", " : "") << number(settings_.instants[i], 10);
    j << "],\n  \"criteria\": {\n    \"visibility_level\": " << number(c.minimumLevel, 6)
      << ",\n    \"observer_age_years\": " << number(c.observer.age, 6)
      << ",\n    \"observation_time_s\": " << number(c.observer.seconds, 6)
      << ",\n    \"least_seen_share\": " << number(c.minimumSeenShare, 6)
      << ",\n    \"least_data_share\": " << number(c.minimumCoverage, 6)
      << ",\n    \"jin\": \"S = C / K, K the mean along the line from the eye to the sign's centre\""
      << ",\n    \"jin_view_angle_factor\": " << (c.jinViewAngle ? "true" : "false")
      << ",\n    \"jin_cap_m\": " << (std::isfinite(c.jinCap) ? number(c.jinCap, 6) : std::string("null"))
      << ",\n    \"least_local_visibility_m\": " << number(c.leastLocalVisibility, 6)
      << ",\n    \"legibility\": \"distance <= Z x the sign's height, Z 200 emitting, 100 reflecting (EN 1838)\""
      << ",\n    \"extinction_quoted\": " << jsonString(quotedName(s.quoted))
      << "\n  },\n  \"rays\": " << s.rays << ",\n  \"passes\": " << s.passes << ",\n  \"signs\": [";
    for (size_t i = 0; i < study_.signs().size(); ++i) {
        const Sign& sign = study_.signs()[i].sign;
        j << (i ? "," : "") << "\n    {\"name\": " << jsonString(sign.name) << ", \"kind\": "
          << jsonString(signKindName(sign.kind))
          << ", \"jin_C\": " << number(sign.jinConstant, 6) << "}";
    }
    j << "\n  ],\n  \"smoke\": [";
    for (size_t i = 0; i < settings_.smoke.size(); ++i) {
        const SmokeDescription& d = settings_.smoke[i];
        j << (i ? "," : "") << "\n    {\"name\": " << jsonString(d.name) << ", \"where\": " << jsonString(d.where.str())
          << ", \"key_frames\": " << d.frames->keyFrames().size() << ", \"albedo\": " << number(photopic(d.albedo), 6)
          << ", \"g\": " << number(d.g, 6) << ", \"K_per_unit_633nm\": "
          << (d.extinctionAt633 ? number(*d.extinctionAt633, 6) : std::string("null"))
          << ", \"data\": " << jsonString(dataNote(d)) << "}";
    }
    j << "\n  ],\n  \"empty_fields\": \"no value: luminances and size where the eye is behind the sign; contrast, "
         "threshold, visibility level and its error where the sign is hidden or behind; jin_distance_m in clear air "
         "(no optical depth) unless capped; local_visibility_m where there is no smoke at the eye\"\n}\n";
    writeWhole(settings_.prefix + ".json", [&](std::ostream& out) { out << j.str(); });
}

}  // namespace brume
