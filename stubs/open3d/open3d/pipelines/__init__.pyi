from open3d.pipelines import integration as integration
