// Minimal robot-side publisher of houghloc's inputs in Java (docs/lcm.md). Built and run by the
// tests (tests/lcm_types) against houghloc_lcm_types.jar, so it stays correct.
//   java -cp lcm.jar:houghloc_lcm_types.jar:. RobotPublisher [LCM_URL]
import lcm.lcm.LCM;

public class RobotPublisher {
  public static void main(String[] args) throws Exception {
    LCM lcm = args.length > 0 ? new LCM(args[0]) : new LCM();  // default: LCM_DEFAULT_URL
    // Microseconds of the robot's monotonic clock (the one the camera driver stamps images with).
    long t = System.nanoTime() / 1000;

    houghloc.odometry_t odometry = new houghloc.odometry_t();
    odometry.utime = t;
    odometry.x = 1.25;  // cumulative, m
    odometry.y = -0.10;
    odometry.theta = 0.05;  // rad; covariance all zero = unknown
    lcm.publish("ODOMETRY", odometry);

    houghloc.camera_pose_t camera = new houghloc.camera_pose_t();
    camera.utime = t;
    camera.camera_id = "top";
    camera.x = 0.05;
    camera.z = 0.52;
    camera.pitch = 0.37;  // rad, positive looks down
    lcm.publish("CAMERA_POSE", camera);

    houghloc.localization_hint_t hint = new houghloc.localization_hint_t();
    hint.utime = t;
    hint.kind = houghloc.localization_hint_t.OWN_HALF;  // from the game state: kick-off
    hint.num_poses = 0;
    hint.poses = new houghloc.pose_hypothesis_t[0];
    lcm.publish("HINT", hint);
    lcm.close();
  }
}
