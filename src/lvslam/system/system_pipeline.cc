#include "lvslam/system/system_pipeline.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <variant>

#include <tbb/global_control.h>

#include "lvslam/core/error.h"
#include "lvslam/system/bounded_queue.h"
#include "lvslam/system/final_visual_poses.h"
#include "lvslam/system/stopwatch.h"
#include "lvslam/system/lidar_worker.h"
#include "lvslam/system/online/online_stage.h"
#include "lvslam/system/visual_worker.h"

namespace lvslam::system {

namespace {

using ScanPtr = std::shared_ptr<const LidarScan>;

// The subsystems a mode runs (each absent when not needed), and the visual
// front end's extractor, run by its own thread ahead of the visual subsystem.
struct Workers {
  std::unique_ptr<LidarWorker> lidar;
  std::unique_ptr<VisualWorker> visual;
  std::unique_ptr<visual::FeatureExtractor> extractor;
  std::optional<PinholeCamera> camera;  // for the fusion framework's segments
};

Workers makeWorkers(const SensorSource& source, const SystemConfig& config) {
  const std::string where = std::string("mode ") + runModeName(config.mode);
  const bool want_lidar = config.mode != RunMode::kVisual;
  const bool want_visual = config.mode != RunMode::kLidar;
  if (want_lidar && !source.hasLidar()) throw Error(where, "needs a recording with a LiDAR");
  if (want_visual && !source.hasCamera()) throw Error(where, "needs a recording with a camera");
  Workers workers;
  const Calibration calibration = source.calibration();
  if (want_lidar) workers.lidar = std::make_unique<LidarWorker>(config, calibration);
  if (want_visual) {
    workers.visual = std::make_unique<VisualWorker>(config, calibration, source.hasLidar());
    workers.extractor = std::make_unique<visual::FeatureExtractor>(config.visual.modules.features, *calibration.camera);
    workers.camera = *calibration.camera;
  }
  return workers;
}

// One camera frame's exchange between the threads: the extraction thread's
// line segments to the LiDAR thread (so the sweep's registration never waits
// for tracking), the keypoints of a new keyframe from the visual thread
// when the fusion framework gives their depth, and its answer back.
struct FrameExchange {
  std::promise<std::vector<fusion::ImageSegment>> segments;
  std::promise<std::vector<Eigen::Vector2d>> keyframe_keypoints;
  std::promise<FusionAnswer> fusion;
  std::future<std::vector<fusion::ImageSegment>> segments_future = segments.get_future();
  std::future<std::vector<Eigen::Vector2d>> keyframe_keypoints_future = keyframe_keypoints.get_future();
  std::future<FusionAnswer> fusion_future = fusion.get_future();
};
using ExchangePtr = std::shared_ptr<FrameExchange>;

template <typename T>
void failPromise(std::promise<T>& promise, std::exception_ptr error) {
  try {
    promise.set_exception(error);
  } catch (const std::future_error&) {
    // Already answered: the other thread has what it needs.
  }
}

struct LidarFrameJob {
  double t = 0.0;
  ExchangePtr exchange;  // null in lidar mode (no segments)
};
struct ImageJob {
  ImageFrame image;
  ExchangePtr exchange;  // null in visual mode (no fusion)
};
struct VisualFrameJob {
  visual::ExtractedImage image;
  double extract_ms = 0.0;
  ExchangePtr exchange;
};
// The sweep before the next scan has ended: every camera frame of it has
// been handed on, so it can be registered (before the next scan arrives).
struct SweepEndJob {};
using LidarJob = std::variant<ScanPtr, LidarFrameJob, SweepEndJob>;
// Scans pass the extraction thread unchanged, so that the visual thread sees
// scans and frames in reading order (its depth hints come from the scans).
using ExtractionJob = std::variant<ScanPtr, ImageJob>;
using VisualJob = std::variant<ScanPtr, VisualFrameJob>;

// The first failure of any thread; the others then stop processing.
class Failure {
 public:
  void record(std::exception_ptr error) {
    std::lock_guard lock(mutex_);
    if (!first_) first_ = error;
    failed_ = true;
  }
  bool failed() const { return failed_; }
  std::exception_ptr first() const { return first_; }

 private:
  std::mutex mutex_;
  std::exception_ptr first_;
  std::atomic<bool> failed_{false};
};

// The fusion framework on one camera frame: its segments, then (only when
// asked for) the keypoints of a new keyframe, whose LiDAR depth comes back too.
template <typename KeypointsOf>
FusionAnswer fuseFrame(LidarWorker& worker, double t, const std::vector<fusion::ImageSegment>& segments,
                       KeypointsOf keyframe_keypoints) {
  FusionAnswer answer = worker.addFrame(t, segments);
  if (worker.answersKeypointDepths()) answer.keypoint_depths = worker.keypointDepths(keyframe_keypoints());
  return answer;
}

void runLidarJob(LidarWorker& worker, LidarJob& job) {
  if (auto* scan = std::get_if<ScanPtr>(&job)) return worker.addScan(**scan);
  if (std::holds_alternative<SweepEndJob>(job)) return worker.endSweep();
  auto& frame = std::get<LidarFrameJob>(job);
  if (!frame.exchange) {
    worker.addFrame(frame.t, {});
    return;
  }
  try {
    FrameExchange& exchange = *frame.exchange;
    exchange.fusion.set_value(fuseFrame(worker, frame.t, exchange.segments_future.get(),
                                        [&exchange] { return exchange.keyframe_keypoints_future.get(); }));
  } catch (...) {
    failPromise(frame.exchange->fusion, std::current_exception());
    throw;
  }
}

// Timed: the visual record keeps the extraction time.
VisualFrameJob extractFrame(visual::FeatureExtractor& extractor, const ImageJob& frame) {
  const Stopwatch watch;
  visual::ExtractedImage image = visual::extractImage(extractor, frame.image);
  return VisualFrameJob{std::move(image), watch.ms(), frame.exchange};
}

void failExchange(FrameExchange& exchange, std::exception_ptr error) {
  failPromise(exchange.segments, error);
  failPromise(exchange.keyframe_keypoints, error);
}

VisualJob extract(visual::FeatureExtractor& extractor, const PinholeCamera& camera, ExtractionJob& job) {
  if (auto* scan = std::get_if<ScanPtr>(&job)) return *scan;
  auto& frame = std::get<ImageJob>(job);
  try {
    VisualFrameJob extracted = extractFrame(extractor, frame);
    if (frame.exchange) frame.exchange->segments.set_value(fusionSegments(extracted.image, camera));
    return extracted;
  } catch (...) {
    if (frame.exchange) failExchange(*frame.exchange, std::current_exception());
    throw;
  }
}

// Tracks a frame and hands its record to the online output.
std::vector<Eigen::Vector2d> trackFrame(VisualWorker& worker, VisualFrameJob& frame, OnlineStage& stage) {
  std::vector<Eigen::Vector2d> keyframe_keypoints = worker.track(std::move(frame.image), frame.extract_ms);
  stage.visualReady(worker.frameCount() - 1, worker.lastFrame());
  return keyframe_keypoints;
}

void runVisualJob(VisualWorker& worker, VisualJob& job, OnlineStage& stage) {
  if (auto* scan = std::get_if<ScanPtr>(&job)) return worker.addScan(*scan);
  auto& frame = std::get<VisualFrameJob>(job);
  try {
    std::vector<Eigen::Vector2d> keyframe_keypoints = trackFrame(worker, frame, stage);
    if (!frame.exchange) return;
    frame.exchange->keyframe_keypoints.set_value(std::move(keyframe_keypoints));
    worker.applyFusion(frame.exchange->fusion_future.get());
  } catch (...) {
    if (frame.exchange) failPromise(frame.exchange->keyframe_keypoints, std::current_exception());
    throw;
  }
}

// After a failure the jobs left are not run, but their partners are told, so
// that no thread waits for an answer that will not come.
void abandon(LidarJob& job, std::exception_ptr error) {
  if (auto* frame = std::get_if<LidarFrameJob>(&job); frame && frame->exchange)
    failPromise(frame->exchange->fusion, error);
}
void abandon(VisualJob& job, std::exception_ptr error) {
  if (auto* frame = std::get_if<VisualFrameJob>(&job); frame && frame->exchange)
    failPromise(frame->exchange->keyframe_keypoints, error);
}
void abandon(ExtractionJob& job, std::exception_ptr error) {
  if (auto* frame = std::get_if<ImageJob>(&job); frame && frame->exchange) failExchange(*frame->exchange, error);
}

template <typename Job, typename Run>
void workerLoop(BoundedQueue<Job>& queue, Failure& failure, Run run, const std::function<void()>& close_all) {
  while (auto job = queue.pop()) {
    if (failure.failed()) {
      abandon(*job, failure.first());
      continue;
    }
    try {
      run(*job);
    } catch (...) {
      failure.record(std::current_exception());
      close_all();
      abandon(*job, failure.first());
    }
  }
}

PipelineRecords collect(Workers& workers, OnlineStage& stage, bool relocate, PipelineRecords records) {
  if (workers.visual) records.visual = workers.visual->takeFrames();
  if (workers.lidar) {
    records.lidar = workers.lidar->takeFrames();
    records.scans = workers.lidar->takeScans();
  }
  stage.finish(records.visual, records.lidar);
  records.online_end = std::chrono::steady_clock::now();
  records.online = stage.takeFrames();
  records.estimator_graph = stage.takeGraph();
  records.switches = stage.output().switches();
  records.T_world_map = stage.output().mapPlacements();
  if (workers.lidar) {
    records.T_odom_lidar_scans = workers.lidar->scanTrajectory();
    records.lidar_map = workers.lidar->map().points();
    records.loop = workers.lidar->finishLoopClosure();
    records.loop_keyframes = workers.lidar->takeLoopKeyframes();
    records.lidar_map_keyframe_starts = workers.lidar->mapKeyframeStarts();
    records.extrinsic_checks = workers.lidar->extrinsicVerdicts();
  }
  if (workers.visual) {
    const visual::VisualSlam& slam = workers.visual->slam();
    placeOnFinalKeyframes(slam.retiredMaps(), slam.map(), records.visual);
    if (relocate) relocateInFinalMaps(slam, records.visual);
    const auto addLines = [&records](const visual::VisualMap& map, int map_id) {
      for (const auto& [id, line] : map.lines())
        records.visual_lines.push_back(
            {line.start_world, line.end_world, line.from_fusion, map_id, visual::firstSeen(map, line.observations)});
    };
    for (std::size_t id = 0; id < slam.retiredMaps().size(); ++id)
      addLines(slam.retiredMaps()[id], static_cast<int>(id));
    addLines(slam.map(), slam.mapId());
  }
  return records;
}

// When a live sensor hands the item over: an image at its time stamp, a
// sweep when its last point is measured.
double deliveryTime(const SensorData& item) {
  if (const auto* image = std::get_if<ImageFrame>(&item)) return image->timestamp;
  const LidarScan& scan = std::get<LidarScan>(item);
  float last = 0.0f;
  if (scan.has_time)
    for (const LidarPoint& p : scan.points) last = std::max(last, p.time);
  return scan.timestamp + static_cast<double>(last);
}

void noteTime(PipelineRecords& records, std::size_t items_before, double t) {
  if (items_before == 0) records.first_time = t;
  records.last_time = t;
}

}  // namespace

PipelineRecords runPipeline(SensorSource& source, const SystemConfig& config, const ProgressCallback& progress,
                            const FrameOutputCallback& on_frame) {
  Workers workers = makeWorkers(source, config);
  OnlineStage stage(makeOnlineOutput(config, source.calibration().T_camera_lidar), workers.visual != nullptr,
                    workers.lidar != nullptr);
  if (on_frame) stage.onFrameOutput(on_frame);
  if (workers.lidar)
    workers.lidar->onFramePosed([&stage](std::size_t index, const LidarFrameRecord& record) {
      stage.lidarReady(index, record);
    });
  // Bit-identical runs need TBB's loops on one thread too.
  std::optional<tbb::global_control> one_thread;
  if (config.deterministic) one_thread.emplace(tbb::global_control::max_allowed_parallelism, 1);

  BoundedQueue<LidarJob> lidar_queue(8);
  BoundedQueue<ExtractionJob> extraction_queue(4);
  BoundedQueue<VisualJob> visual_queue(4);
  Failure failure;
  const auto close_all = [&] {
    lidar_queue.close();
    extraction_queue.close();
    visual_queue.close();
  };
  // Deterministic: the same jobs, run in reading order on this thread.
  const bool threaded = !config.deterministic;
  std::thread lidar_thread, extraction_thread, visual_thread;
  if (threaded && workers.lidar)
    lidar_thread = std::thread([&] {
      workerLoop(lidar_queue, failure, [&](LidarJob& job) { runLidarJob(*workers.lidar, job); }, close_all);
      if (!failure.failed()) {
        try {
          workers.lidar->finish();
        } catch (...) {
          failure.record(std::current_exception());
        }
      }
    });
  if (threaded && workers.visual) {
    // Extraction is stateless: frame k+1 is extracted while frame k is tracked.
    extraction_thread = std::thread([&] {
      workerLoop(
          extraction_queue, failure,
          [&](ExtractionJob& job) {
            VisualJob next = extract(*workers.extractor, *workers.camera, job);
            if (!visual_queue.push(std::move(next))) abandon(next, failure.first());
          },
          close_all);
      visual_queue.close();  // after the last frame: the visual thread drains and ends
    });
    visual_thread = std::thread([&] {
      workerLoop(visual_queue, failure, [&](VisualJob& job) { runVisualJob(*workers.visual, job, stage); }, close_all);
    });
  }

  const auto toLidar = [&](LidarJob job) {
    if (threaded) return lidar_queue.push(std::move(job));
    runLidarJob(*workers.lidar, job);
    return true;
  };
  const auto toVisual = [&](ExtractionJob job) {
    if (threaded) return extraction_queue.push(std::move(job));
    VisualJob extracted = extract(*workers.extractor, *workers.camera, job);
    runVisualJob(*workers.visual, extracted, stage);
    return true;
  };

  PipelineRecords records;
  std::size_t scans = 0;
  std::exception_ptr reading_error;
  // Live pace: an item is handed on no earlier than a live sensor would
  // deliver it (an image at its time stamp, a sweep at its last point), and
  // a frame's latency counts from then.
  const auto wall_start = std::chrono::steady_clock::now();
  std::optional<double> data_start;
  const auto due = [&](double t) {
    if (!data_start) data_start = t;
    return wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(t - *data_start));
  };
  const auto paceTo = [&](double t) {
    if (config.realtime) std::this_thread::sleep_until(due(t));
  };
  // A source that cannot be read further ends the recording there.
  const auto readNext = [&]() -> std::optional<SensorData> {
    try {
      return source.next();
    } catch (const Error& fault) {
      records.input_fault = fault;
      return std::nullopt;
    }
  };
  try {
    while (auto data = readNext()) {
      if (failure.failed()) break;
      bool ok = true;
      if (auto* scan = std::get_if<LidarScan>(&*data)) {
        // A scan's time stamp is its first point's: the sweep before it ends then.
        paceTo(scan->timestamp);
        if (workers.lidar) ok = toLidar(SweepEndJob{});
        if (config.realtime) paceTo(deliveryTime(*data));
        noteTime(records, records.images + scans, scan->timestamp);
        ++scans;
        const ScanPtr shared = std::make_shared<const LidarScan>(std::move(*scan));
        if (workers.visual) ok = toVisual(shared);
        if (ok && workers.lidar) ok = toLidar(shared);
        if (progress) progress(shared->timestamp, records.images, scans);
      } else {
        auto& image = std::get<ImageFrame>(*data);
        paceTo(image.timestamp);
        noteTime(records, records.images + scans, image.timestamp);
        stage.frameArrived(records.images, config.realtime ? due(image.timestamp) : std::chrono::steady_clock::now());
        ++records.images;
        const double t = image.timestamp;
        // The fusion framework needs both subsystems of this frame.
        const ExchangePtr exchange =
            workers.lidar && workers.visual && threaded ? std::make_shared<FrameExchange>() : nullptr;
        if (workers.visual && !threaded) {
          VisualFrameJob frame = extractFrame(*workers.extractor, ImageJob{std::move(image), nullptr});
          const std::vector<fusion::ImageSegment> segments = fusionSegments(frame.image, *workers.camera);
          const std::vector<Eigen::Vector2d> keyframe_keypoints = trackFrame(*workers.visual, frame, stage);
          if (workers.lidar)
            workers.visual->applyFusion(fuseFrame(*workers.lidar, t, segments, [&] { return keyframe_keypoints; }));
        } else {
          if (workers.visual) ok = toVisual(ImageJob{std::move(image), exchange});
          if (ok && workers.lidar) ok = toLidar(LidarFrameJob{t, exchange});
          // Refused after a failure: the visual thread may already wait for this fusion answer.
          if (!ok && exchange) failPromise(exchange->fusion, failure.first());
        }
        if (progress) progress(t, records.images, scans);
      }
      if (!ok) break;
    }
    if (!threaded && workers.lidar) workers.lidar->finish();
  } catch (...) {
    reading_error = std::current_exception();
    failure.record(reading_error);
  }
  // The LiDAR and extraction queues end here; the visual queue when the
  // extraction thread has handed over its last frame.
  lidar_queue.close();
  extraction_queue.close();
  if (lidar_thread.joinable()) lidar_thread.join();
  if (extraction_thread.joinable()) extraction_thread.join();
  visual_queue.close();
  if (visual_thread.joinable()) visual_thread.join();
  if (reading_error) std::rethrow_exception(reading_error);
  if (failure.first()) std::rethrow_exception(failure.first());
  records.scans_read = scans;
  return collect(workers, stage, relocatesInFinalMaps(config), std::move(records));
}

}  // namespace lvslam::system
